"""granular.spreading, granular.transport and granular.exponent_table: identical numbers to the
spreading and exponents tools on the same chains and seeds, and the conservation law the
integrator must keep."""
import inspect
import json
import re

import numpy as np
import pytest

import granular as gr
from conftest import assert_identical, read_csv

SHORT = dict(T=1e-3, fit=(2e-4, 1e-3))
SHORT_FLAGS = ["--T", "1e-3", "--fit", "2e-4:1e-3"]
PROCESS_KEYS = {"command", "started_utc", "wall_time_s", "output", "tool", "function"}


def without_process_keys(meta):
    """The metadata minus what only a process or a clock has (the integration's wall time)."""
    meta = {k: v for k, v in meta.items() if k not in PROCESS_KEYS}
    if "run" in meta:
        meta["run"] = {k: v for k, v in meta["run"].items() if k != "integration_s"}
    return meta


def test_one_run_with_every_observer_equals_the_spreading_tool(tools):
    args = ["--disorder", "A", "--N", "201", "--F0", "10", "--seed", "3", "--realization", "1", *SHORT_FLAGS,
            "--final-state", tools.path("f.csv"), "--energy-map", tools.path("m.h5"), "--map-samples", "50",
            "--spectrum", tools.path("s.csv"), "--spectrum-samples", "100", "--forces-at", "90,101",
            "--force-samples", "50"]
    csv, meta = tools.run("spreading", *args, output="one")
    run = gr.spreading(gr.anderson(N=201, F0=10, seed=3, realization=1), **SHORT, energy_map=True, map_samples=50,
                       spectral_density=True, spectrum_samples=100, forces_at=[90, 101], force_samples=50)
    for key in ("t", "m2", "ipr", "energy_error", "m2_centroid"):
        assert_identical(run[key], csv[key])
    final = read_csv(tools.path("f.csv"))
    for key in ("u", "v", "energy"):
        assert_identical(run.final_state[key], final[key])
    g = read_csv(tools.path("s.csv"))
    assert_identical(run.spectral_density["freq_khz"], g["freq_khz"])
    assert_identical(run.spectral_density["g"], g["g"])
    forces = read_csv(tools.path("one-forces.csv"))
    assert_identical(run.forces["force"].T.ravel(), forces["force"])  # the CSV is time-major
    assert_identical(np.repeat(run.forces["t"], 2), forces["t"])
    import h5py  # after granular: each loads its own HDF5 library, privately

    with h5py.File(tools.path("m.h5"), "r") as f:
        assert_identical(run.energy_map["energy"], np.array(f["energy"]))
        assert_identical(run.energy_map["t"], np.array(f["t"]))
        assert_identical(run.energy_map["site"], np.array(f["site"]))
    mine, theirs = without_process_keys(run.metadata), without_process_keys(meta)
    assert theirs["spectrum"].pop("file") == str(tools.path("s.csv"))
    assert mine == theirs
    assert run.gamma == meta["gamma"] and run.eta == meta["eta"] and run.exponents == meta["exponents"]


def test_velocity_kick_at_a_chosen_site_equals_the_spreading_tool(tools):
    csv, meta = tools.run("spreading", "--disorder", "RDM2", "--N", "151", "--F0", "0.5", "--ic", "velocity",
                          "--beta", "match", "--site", "60", "--integrator", "aba864", "--samples", "80", *SHORT_FLAGS,
                          output="vel")
    run = gr.spreading(gr.rdm2(N=151, F0=0.5), ic="velocity", beta="match", site=60, integrator="aba864", samples=80,
                       **SHORT)
    assert_identical(run.m2, csv["m2"])
    assert_identical(run.m2_centroid, csv["m2_centroid"])
    assert_identical(run.ipr, csv["ipr"])
    assert run.metadata["parameters"]["beta_used"] == meta["parameters"]["beta_used"] > 0
    assert without_process_keys(run.metadata) == without_process_keys(meta)


def test_energy_is_conserved_and_a_homogeneous_chain_spreads_ballistically():
    run = gr.spreading(gr.homogeneous(N=1001, F0=10), T=2e-3, fit=(5e-4, 2e-3), integrator="srkn14a")
    assert run.max_energy_error < 1e-8
    total = run.final_state["energy"].sum()
    assert total == pytest.approx(run.initial_energy, rel=1e-6)  # walls not reached: sum E_n is H
    assert not run.reached_walls
    assert run.gamma == pytest.approx(2.0, abs=0.05)  # docs/physics.md, "Nonlinear dynamics": ballistic, m2 ~ t^2
    # m2 about the site = m2 about the centroid + (centroid - site)^2 >= m2 about the centroid
    assert np.all(run.m2 >= run.m2_centroid * (1 - 1e-12))


def test_ensemble_equals_the_spreading_tool(tools):
    csv, meta = tools.run("spreading", "--disorder", "A", "--N", "201", "--realizations", "4", "--threads", "2",
                          "--profile", *SHORT_FLAGS, output="ens")
    t = gr.transport(disorder="A", N=201, realizations=4, threads=2, profile=True, **SHORT)
    for key in ("t", "m2", "ipr", "energy_error", "m2_centroid"):
        assert_identical(t[key], csv[key])
    sem = read_csv(tools.path("ens-sem.csv"))
    for key in ("m2_se", "ipr_se", "energy_error_se", "m2_centroid_se"):
        assert_identical(t[key], sem[key])
    profile = read_csv(tools.path("ens-profile.csv"))
    assert_identical(t.profile["energy"], profile["energy"])
    assert_identical(t.profile["energy_se"], profile["energy_se"])
    mine, theirs = without_process_keys(t.metadata), without_process_keys(meta)
    assert mine == theirs
    assert t.gamma_real_err == meta["gamma_real_err"] > 0  # the realization bootstrap


def test_realizations_in_lanes_are_the_same_bits_as_one_at_a_time():
    # 19 realizations: whole batches of 8 (4, 2: the CPU's lanes) side by side, and the rest alone.
    lanes = gr.transport(disorder="RDM1", N=151, realizations=19, threads=2, profile=True, **SHORT)
    alone = gr.transport(disorder="RDM1", N=151, realizations=19, threads=1, profile=True, one_at_a_time=True,
                         **SHORT)
    for key in ("m2", "m2_se", "ipr", "energy_error", "m2_centroid"):
        assert_identical(lanes[key], alone[key])
    assert_identical(lanes.profile["energy"], alone.profile["energy"])
    assert lanes.gamma == alone.gamma and lanes.gamma_real_err == alone.gamma_real_err


@pytest.mark.parametrize("keyword, text", [("types", "4.76e-3:0.5,2.38e-3:0.5"),
                                           ("polydisperse", "uniform:3e-3:4.76e-3")])
def test_ensemble_of_a_bead_distribution_equals_the_spreading_tool(tools, keyword, text):
    """transport(types=...) / transport(polydisperse=...) is spreading --types/--polydisperse --realizations: the
    case made by the same library rule (kicked_case), the same chains drawn."""
    flag = "--" + keyword
    rule = {"disorder": "RDM1"} if keyword == "types" else {}  # how k types are drawn; polydisperse radii: per bead
    csv, meta = tools.run("spreading", *[w for k, v in rule.items() for w in ("--" + k, v)], "--N", "121",
                          "--realizations", "3", flag, text, *SHORT_FLAGS, output="dist")
    t = gr.transport(**rule, N=121, realizations=3, **{keyword: text}, **SHORT)
    with pytest.raises(ValueError, match=r"disorder: takes no effect with polydisperse"):
        gr.transport(disorder="RDM1", polydisperse="uniform:3e-3:4e-3", **SHORT)
    for key in ("t", "m2", "ipr", "energy_error"):
        assert_identical(t[key], csv[key])
    assert without_process_keys(t.metadata) == without_process_keys(meta)
    with pytest.raises(ValueError, match=r"polydisperse: not with types"):
        gr.transport(types="4.76e-3:1", polydisperse="uniform:3e-3:4e-3", **SHORT)


def test_mode_kicks_of_an_ensemble_and_of_the_table_equal_the_tools(tools):
    """transport(ic='mode', mode=...) is spreading --ic mode --mode ... --realizations, and exponent_table's mode kick
    is exponents --ic mode --mode ...: each realization kicked with its own chain's mode, by the library's rule."""
    csv, meta = tools.run("spreading", "--disorder", "RDM1", "--N", "121", "--realizations", "3", "--ic", "mode",
                          "--mode", "7", "--energy", "1e-9", *SHORT_FLAGS, output="mode")
    with pytest.warns(RuntimeWarning, match="reached the walls"):  # a mode spans the chain, walls included
        t = gr.transport(disorder="RDM1", N=121, realizations=3, ic="mode", mode=7, energy=1e-9, **SHORT)
    for key in ("t", "m2", "ipr", "energy_error"):
        assert_identical(t[key], csv[key])
    assert without_process_keys(t.metadata) == without_process_keys(meta)
    flags = ["--chains", "A", "--F0", "1", "--ic", "mode", "--near", "12", "--N", "101", "--realizations", "2",
             "--samples", "30", "--profile-F0", "none", "--bootstrap", "50", *SHORT_FLAGS, "--quiet"]
    csv, meta = tools.run("exponents", *flags, output="exp")
    table = gr.exponent_table(chains=["A"], F0=[1], ic=["mode"], near=12, N=101, realizations=2, samples=30,
                              profile_F0=None, bootstrap=50, **SHORT)
    assert list(table.column("ic")) == ["mode"]
    assert_columns_identical(table, csv)
    assert without_process_keys(table.metadata) == without_process_keys(meta)
    with pytest.raises(ValueError, match="only with `?ic`? mode"):
        gr.exponent_table(chains=["h"], mode=3, **SHORT)


def test_skip_failed_leaves_out_the_failing_realization_as_the_tools_do(tools):
    """transport(skip_failed=True) is spreading --skip-failed: the realization whose energy error passes the guard
    is left out of the means, named in the metadata and warned about; without it the call raises. The guard sits
    between the worst realization's error and the next one's (each run alone, the guard only watching)."""
    case = dict(xi=0.5, q=0.5, N=101, F0=0.01, ic="velocity", seed=3, T=1e-3, dt=2e-6, fit=(4e-4, 1e-3), samples=30,
                bootstrap=50)
    chains = [gr.anderson(N=101, xi=0.5, q=0.5, F0=0.01, seed=3, realization=r) for r in range(6)]
    worst = [gr.spreading(c, ic="velocity", T=1e-3, dt=2e-6, fit=(4e-4, 1e-3), samples=30, bootstrap=50,
                          energy_guard="warn").max_energy_error for c in chains]
    second, first = sorted(worst)[-2:]
    assert first > 1.2 * second, "no realization stands out; change the case"
    guard, failing = float(f"{np.sqrt(first * second):.6g}"), int(np.argmax(worst))
    with pytest.raises(gr.NumericalError, match=f"realization {failing} of seed 3"):
        gr.transport(realizations=6, max_energy_error=guard, **case)
    csv, meta = tools.run("spreading", "--disorder", "A", "--xi", "0.5", "--q", "0.5", "--N", "101", "--F0", "0.01",
                          "--ic", "velocity", "--seed", "3", "--T", "1e-3", "--dt", "2e-6", "--fit", "4e-4:1e-3",
                          "--samples", "30", "--bootstrap", "50", "--realizations", "6", "--max-energy-error",
                          repr(guard), "--skip-failed", "--quiet", output="skip")
    with pytest.warns(RuntimeWarning, match=r"1 failed realization\(s\) of 6 left out"):
        t = gr.transport(realizations=6, max_energy_error=guard, skip_failed=True, **case)
    assert t.metadata["ensemble"]["failed_excluded"] == [failing] == meta["ensemble"]["failed_excluded"]
    assert t.realizations == 5
    for key in ("t", "m2", "ipr", "energy_error"):
        assert_identical(t[key], csv[key])


def test_ensemble_mean_is_the_mean_of_the_single_runs():
    t = gr.transport(disorder="RDM1", N=121, realizations=3, seed=2, **SHORT)
    runs = [gr.spreading(gr.rdm1(N=121, seed=2, realization=r), **SHORT) for r in range(3)]
    np.testing.assert_allclose(t.m2, np.mean([r.m2 for r in runs], axis=0), rtol=1e-14)
    np.testing.assert_allclose(t.ipr, np.mean([r.ipr for r in runs], axis=0), rtol=1e-14)


def assert_columns_identical(table, csv):
    """Every column of the tool's PREFIX.csv equals the table's: flags as the CSV spells them, words
    as they are, numbers to the last digit."""
    for key, column in csv.items():
        mine = table.column(key)
        if mine.dtype == bool:
            assert [str(v).lower() for v in mine] == column, key
        elif isinstance(column, list):
            assert list(mine) == column, key
        else:
            assert_identical(mine, column)


def test_exponent_table_equals_the_exponents_tool(tools):
    flags = ["--chains", "h,A", "--F0", "10,0", "--ic", "displacement,velocity", "--N", "151", "--realizations", "3",
             "--samples", "60", "--profile-F0", "10", "--profile-realizations", "2", "--bootstrap", "50", *SHORT_FLAGS,
             "--compare-paper", "--quiet"]
    csv, meta = tools.run("exponents", *flags, output="exp")
    table = gr.exponent_table(chains=["h", "A"], F0=[10, 0], ic=["displacement", "velocity"], N=151, realizations=3,
                              samples=60, profile_F0=[10], profile_realizations=2, bootstrap=50, compare_paper=True,
                              **SHORT)
    assert set(table.table) == set(csv)
    assert_columns_identical(table, csv)
    curves = read_csv(tools.path("exp-curves.csv"))
    for key in ("t", "m2", "m2_centroid", "ipr", "m2_se"):
        assert_identical(np.concatenate([c[key] for c in table.curves]), curves[key])
    profiles = read_csv(tools.path("exp-profiles.csv"))
    assert_identical(np.concatenate([p["energy"] for p in table.profiles]), profiles["energy"])
    assert table.metadata["cases"] == meta["cases"]
    paper = read_csv(tools.path("exp-paper.csv"))
    assert_identical(table.paper["site_z"], paper["site_z"])
    assert "| F0 [N] | h | A |" in table.markdown
    row = table.cell("velocity", 0.0, "A")
    assert row["realizations"] == 3 and row["gamma"] == table.column("gamma")[7]  # kick-major, then F0, then chain


def test_a_mode_kick_equals_the_spreading_tool_and_keeps_its_mode_under_the_linear_law(tools):
    args = ["--disorder", "A", "--N", "101", "--seed", "2", "--ic", "mode", "--near", "30", "--energy", "1e-7",
            "--force-law", "linear", *SHORT_FLAGS]
    csv, meta = tools.run("spreading", *args, output="mode")
    run = gr.spreading(gr.anderson(N=101, seed=2), ic="mode", near=30, energy=1e-7, force_law="linear", **SHORT)
    for key in ("t", "m2", "ipr", "m2_centroid"):
        assert_identical(run[key], csv[key])
    used = run.metadata["parameters"]["mode_used"]
    assert used == meta["parameters"]["mode_used"]
    assert abs(used["energy_J"] - 1e-7) < 1e-20
    # One linear mode, nothing to spread into: m2 oscillates with the mode but does not grow.
    assert np.max(run["m2_centroid"]) < 3 * run["m2_centroid"][0] + 2
    with pytest.raises(ValueError):
        gr.spreading(gr.anderson(N=101, seed=2), mode=3, **SHORT)  # a mode without ic='mode'


def test_default_time_step_follows_the_stability_rule():
    """dt=None: 1 us where stable with margin, else 1 us/k (as the tools without --dt); the rule in the metadata."""
    paper = gr.spreading(gr.anderson(N=51), T=1e-4, fit=(2e-5, 1e-4), samples=20)
    assert paper.metadata["time_step_rule"]["time_step_s"] == 1e-6
    small = gr.spreading(gr.anderson(N=51, xi=0.05), T=1e-4, fit=(2e-5, 1e-4), samples=20)
    rule = small.metadata["time_step_rule"]
    assert rule["time_step_given"] is False
    assert rule["time_step_s"] < 1e-6 and rule["time_step_s"] <= rule["max_time_step_s"] / 6
    assert small.metadata["parameters"]["time_step"] == rule["time_step_s"]
    assert small.max_energy_error < 1e-3


def test_automatic_integrator_equals_the_spreading_tool(tools):
    """integrator='auto' is the tools' --integrator auto: SRKN14a at 5 us where no contact can open, SABA2C in
    the sonic vacuum; identical numbers and the choice in the metadata; dt with it is refused."""
    csv, meta = tools.run("spreading", "--disorder", "A", "--N", "201", "--F0", "10", "--integrator", "auto",
                          *SHORT_FLAGS, output="auto")
    run = gr.spreading(gr.anderson(N=201, F0=10), integrator="auto", **SHORT)
    assert run.metadata["time_step_rule"]["integrator_choice"]["integrator"] == "srkn14a"
    assert run.metadata["parameters"]["time_step"] == 5e-6
    assert_identical(run.m2, csv["m2"])
    assert_identical(run.ipr, csv["ipr"])
    assert without_process_keys(run.metadata) == without_process_keys(meta)
    vacuum = gr.spreading(gr.anderson(N=201, F0=0), integrator="auto", **SHORT)
    assert vacuum.metadata["time_step_rule"]["integrator_choice"]["integrator"] == "saba2c"
    assert vacuum.metadata["parameters"]["time_step"] == 1e-6
    with pytest.raises(ValueError, match="dt"):
        gr.spreading(gr.anderson(N=201, F0=10), integrator="auto", dt=1e-6, **SHORT)


# --- beyond the paper: dissipation and the maximal Lyapunov exponent ----------------------------------


def test_damped_run_equals_the_spreading_tool(tools):
    """damping_time and kk_gamma are the tool's --damping-time and --kk-gamma: the same columns, `dissipated` too."""
    csv, meta = tools.run("spreading", "--disorder", "A", "--N", "151", "--F0", "1", "--seed", "2", "--damping-time",
                          "2e-3", "--kk-gamma", "1e-6", *SHORT_FLAGS, output="damped")
    run = gr.spreading(gr.anderson(N=151, F0=1, seed=2), damping_time=2e-3, kk_gamma=1e-6, **SHORT)
    assert "dissipated" in csv and "mle" not in csv
    for key in ("t", "m2", "ipr", "energy_error", "m2_centroid", "dissipated"):
        assert_identical(run[key], csv[key])
    assert run.mle is None and run.deviation is None
    assert run.dissipated[-1] > 0 and np.all(np.diff(run.dissipated) >= 0)
    assert run.metadata["parameters"]["damping_time"] == 2e-3 and run.metadata["parameters"]["kk_gamma"] == 1e-6
    assert run.metadata["run"]["dissipated_J"] == run.dissipated[-1]
    assert without_process_keys(run.metadata) == without_process_keys(meta)
    plain = gr.spreading(gr.anderson(N=151, F0=1, seed=2), **SHORT)
    assert plain.dissipated is None and "damping" not in plain.metadata["parameters"]


def test_mle_and_deviation_vector_equal_the_spreading_tool(tools):
    """mle=True is --mle (column mle = X1(t)); deviation_samples=K is --deviation FILE --deviation-samples K."""
    csv, meta = tools.run("spreading", "--disorder", "A", "--N", "201", "--seed", "2", "--mle", "--renormalize", "5",
                          "--deviation", tools.path("w.csv"), "--deviation-samples", "11", *SHORT_FLAGS, output="mle")
    run = gr.spreading(gr.anderson(N=201, seed=2), mle=True, renormalize=5, deviation_samples=11, **SHORT)
    assert "mle" in csv and "dissipated" not in csv
    for key in ("t", "m2", "ipr", "energy_error", "m2_centroid", "mle"):
        assert_identical(run[key], csv[key])
    assert run.dissipated is None
    w = read_csv(tools.path("w.csv"))
    share = run.deviation["share"]
    assert share.shape == (11, 201)
    assert_identical(share.ravel(), w["share"])  # the CSV is time-major
    assert_identical(np.repeat(run.deviation["t"], 201), w["t"])
    assert_identical(np.tile(run.deviation["site"], 11), w["site"])
    np.testing.assert_allclose(share.sum(axis=1), 1, rtol=1e-12)
    assert run.metadata["parameters"]["renormalize"] == 5
    assert run.metadata["run"]["mle_per_s"] == run.mle[-1]
    assert without_process_keys(run.metadata) == without_process_keys(meta)


def test_norm_time_unit_equals_the_spreading_tool(tools):
    """norm_time_unit= is --norm-time-unit: the tangent map's norm |(du, t_unit dv)|, so X1(t) changes and the orbit
    does not; it is in the metadata, and without mle or at 0 it is refused naming the keyword."""
    csv, meta = tools.run("spreading", "--disorder", "A", "--N", "101", "--mle", "--norm-time-unit", "1e-5",
                          *SHORT_FLAGS, output="unit")
    run = gr.spreading(gr.anderson(N=101), mle=True, norm_time_unit=1e-5, **SHORT)
    plain = gr.spreading(gr.anderson(N=101), mle=True, **SHORT)
    assert_identical(run.mle, csv["mle"])
    assert_identical(run.m2, plain.m2) and not np.array_equal(run.mle, plain.mle)
    assert run.metadata["parameters"]["norm_time_unit"] == 1e-5
    assert without_process_keys(run.metadata) == without_process_keys(meta)
    with pytest.raises(ValueError, match="norm_time_unit"):
        gr.spreading(gr.anderson(N=101), mle=True, norm_time_unit=0, **SHORT)
    with pytest.raises(ValueError, match="norm_time_unit"):
        gr.spreading(gr.anderson(N=101), norm_time_unit=1e-5, **SHORT)


def test_lyapunov_spectrum_equals_the_spreading_tool(tools):
    """lyapunov_vectors=k (with mle=True) is --lyapunov-vectors k: PREFIX-lyapunov.csv holds t, lambda_1..lambda_k,
    gali_2..gali_k and sali at the run's sample times; the run's own curves are those of a run without it."""
    flags = ["--disorder", "A", "--N", "21", "--F0", "0.01", "--ic", "velocity", "--beta", "0.05", "--seed", "2",
             "--mle", "--renormalize", "5", "--samples", "40", *SHORT_FLAGS]
    csv, meta = tools.run("spreading", *flags, "--lyapunov-vectors", "4", output="lyap")
    keywords = dict(ic="velocity", beta=0.05, mle=True, renormalize=5, samples=40, **SHORT)
    chain = gr.anderson(N=21, F0=0.01, seed=2)
    run = gr.spreading(chain, lyapunov_vectors=4, **keywords)
    spectrum = read_csv(tools.path("lyap-lyapunov.csv"))
    header = ["t", "lambda_1", "lambda_2", "lambda_3", "lambda_4", "gali_2", "gali_3", "gali_4", "sali"]
    assert list(spectrum) == header
    lyap = run.lyapunov
    assert lyap["exponents"].shape == (len(run.t), 4) and lyap["gali"].shape == (len(run.t), 3)
    assert_identical(lyap["t"], run.t)
    assert_identical(lyap["t"], spectrum["t"])
    for j in range(4):
        assert_identical(lyap["exponents"][:, j], spectrum[f"lambda_{j + 1}"])
    for j in range(3):
        assert_identical(lyap["gali"][:, j], spectrum[f"gali_{j + 2}"])
    assert_identical(lyap["sali"], spectrum["sali"])
    assert lyap["exponents"][-1, 0] > 0 and lyap["gali"][-1, 2] < lyap["gali"][0, 2] <= 1
    assert meta["lyapunov_spectrum"]["file"].endswith("lyap-lyapunov.csv")
    assert meta["lyapunov_spectrum"]["vectors"] == 4
    assert run.metadata["lyapunov_spectrum"]["exponents_T_per_s"] == list(lyap["exponents"][-1])
    assert run.metadata["parameters"]["lyapunov_vectors"] == 4
    plain = gr.spreading(chain, **keywords)
    assert plain.lyapunov is None
    for key in ("m2", "m2_centroid", "ipr", "energy_error", "mle"):
        assert_identical(run[key], plain[key])
    assert_identical(run.final_state["u"], plain.final_state["u"])
    one = gr.spreading(chain, lyapunov_vectors=1, **keywords).lyapunov
    assert one["exponents"].shape == (len(run.t), 1) and one["gali"].shape == (len(run.t), 0) and one["sali"] is None


def test_covariant_vectors_equal_the_spreading_tools_h5(tools):
    """covariant_vectors=k (with mle=True) is --covariant-vectors k: run.covariant holds PREFIX-clv.h5's arrays under
    its names, bit for bit; the run's own curves are those of a run without it."""
    h5py = pytest.importorskip("h5py")
    flags = ["--N", "8", "--F0", "0.01", "--ic", "velocity", "--beta", "0.05", "--mle", "--renormalize", "7",
             "--T", "2e-4", "--dt", "1e-7", "--samples", "20", "--fit", "1e-4:2e-4", "--fit-step", "1e-5", "--quiet"]
    _, meta = tools.run("spreading", *flags, "--covariant-vectors", "4", "--covariant-transient", "5e-5",
                        output="clv")
    keywords = dict(ic="velocity", beta=0.05, mle=True, renormalize=7, T=2e-4, dt=1e-7, samples=20,
                    fit=(1e-4, 2e-4), fit_step=1e-5)
    chain = gr.anderson(N=8, F0=0.01)
    run = gr.spreading(chain, covariant_vectors=4, covariant_transient=5e-5, **keywords)
    clv = run.covariant
    with h5py.File(tools.path("clv-clv.h5"), "r") as f:
        samples = len(f["t"])
        assert clv["vectors"].shape == (samples, 4, 16)
        assert_identical(clv["vectors"].reshape(-1, 16), np.array(f["vectors"]))
        for name in ("t", "growth_rates", "exponents", "split_angles", "participation", "centre"):
            assert_identical(clv[name], np.array(f[name]))
        units = f.attrs["vectors_units"]
        assert "t_unit = 1e-06 s" in (units.decode() if isinstance(units, bytes) else units)
    assert clv["t"][0] >= 5e-5 and clv["t"][-1] == run.t[-1]
    assert meta["covariant_vectors"]["file"].endswith("clv-clv.h5")
    assert run.metadata["covariant_vectors"]["growth_rates_per_s"] == list(clv["growth_rates"])
    plain = gr.spreading(chain, **keywords)
    assert plain.covariant is None
    for key in ("m2", "m2_centroid", "ipr", "energy_error", "mle"):
        assert_identical(run[key], plain[key])
    one = gr.spreading(chain, covariant_vectors=1, **keywords).covariant
    assert one["vectors"].shape[1:] == (1, 16) and one["split_angles"] is None
    with pytest.raises(ValueError, match="covariant_vectors: takes effect only with `?mle"):
        gr.spreading(chain, covariant_vectors=2, T=2e-4, dt=1e-7, fit=(1e-4, 2e-4))
    with pytest.raises(ValueError, match="covariant_vectors 17: between 1 and 2N = 16"):
        gr.spreading(chain, covariant_vectors=17, **keywords)
    for function in (gr.transport, gr.exponent_table):
        assert "covariant_vectors" not in inspect.signature(function).parameters


def test_lyapunov_vectors_are_refused_where_they_cannot_run():
    """Needs mle (the same tangent map and its rules); 1..2N; one realization (no ensemble keyword)."""
    c = gr.anderson(N=4)
    with pytest.raises(ValueError, match="lyapunov_vectors: takes effect only with `?mle"):
        gr.spreading(c, lyapunov_vectors=2, **SHORT)
    with pytest.raises(ValueError, match="lyapunov_vectors 9: between 1 and 2N = 8"):
        gr.spreading(c, mle=True, lyapunov_vectors=9, **SHORT)
    with pytest.raises(ValueError, match="mle"):
        gr.spreading(c, mle=True, lyapunov_vectors=2, damping_time=1e-3, **SHORT)
    for function in (gr.transport, gr.exponent_table):
        assert "lyapunov_vectors" not in inspect.signature(function).parameters
    assert inspect.signature(gr.spreading).parameters["lyapunov_vectors"].default == 0
    assert re.search(r"lyapunov_vectors", gr.spreading.__doc__)


@pytest.mark.parametrize("flags,keywords", [
    (["--mle"], dict(mle=True)),
    (["--damping-time", "1e-3"], dict(damping_time=1e-3)),
])
def test_ensemble_beyond_the_paper_equals_the_spreading_tool(tools, flags, keywords):
    """transport with mle (the tool's ensemble mean X1(t) in column mle) or with damping."""
    csv, meta = tools.run("spreading", "--disorder", "A", "--N", "201", "--realizations", "3", "--threads", "2",
                          "--bootstrap", "50", *flags, *SHORT_FLAGS, output="ens")
    t = gr.transport(disorder="A", N=201, realizations=3, threads=2, bootstrap=50, **keywords, **SHORT)
    for key in ("t", "m2", "ipr", "energy_error", "m2_centroid"):
        assert_identical(t[key], csv[key])
    assert ("mle" in csv) == ("mle" in keywords)
    if "mle" in keywords:
        assert_identical(t.mle, csv["mle"])
        assert t.mle_se.shape == t.mle.shape and np.all(t.mle_se >= 0) and np.any(t.mle_se > 0)
    else:
        assert t.mle is None and t.mle_se is None
    assert without_process_keys(t.metadata) == without_process_keys(meta)


def test_exponent_table_with_mle_equals_the_exponents_tool(tools):
    """exponent_table(mle=True) is exponents --mle: columns mle, mle_real_err, mle_sd; <X1(t)> in the curves."""
    flags = ["--chains", "A", "--F0", "10", "--ic", "displacement", "--N", "101", "--realizations", "3", "--samples",
             "40", "--profile-F0", "none", "--bootstrap", "50", "--mle", "--renormalize", "20", *SHORT_FLAGS, "--quiet"]
    csv, meta = tools.run("exponents", *flags, output="exp")
    table = gr.exponent_table(chains=["A"], F0=[10], ic=["displacement"], N=101, realizations=3, samples=40,
                              profile_F0=None, bootstrap=50, mle=True, renormalize=20, **SHORT)
    assert {"mle", "mle_real_err", "mle_sd"} <= set(csv)
    assert set(table.table) == set(csv)
    assert_columns_identical(table, csv)
    curves = read_csv(tools.path("exp-curves.csv"))
    for key in ("t", "m2", "ipr", "mle", "mle_se"):
        assert_identical(np.concatenate([c[key] for c in table.curves]), curves[key])
    case = table.metadata["cases"][0]
    assert case["mle_at_T"] == meta["cases"][0]["mle_at_T"] and case["mle_at_T"]["X1_at_T_per_s"] == table.column("mle")[0]
    assert without_process_keys(table.metadata) == without_process_keys(meta)


def test_exponent_table_of_k_bead_types_equals_the_exponents_tool(tools):
    """exponent_table(types=..., types_rule=..., chain_name=...) is exponents --types ... --types-rule ...: the chain
    of one's own after the kinds, drawn by the same rule, under the same name."""
    types = "4.76e-3:0.4,4e-3:0.3,3e-3:0.3"
    flags = ["--chains", "h", "--F0", "1", "--ic", "velocity", "--N", "101", "--realizations", "3", "--samples", "30",
             "--profile-F0", "none", "--bootstrap", "50", "--types", types, "--types-rule", "RDM1", "--chain-name",
             "three", *SHORT_FLAGS, "--quiet"]
    csv, meta = tools.run("exponents", *flags, output="exp")
    table = gr.exponent_table(chains=["h"], F0=[1], ic=["velocity"], N=101, realizations=3, samples=30,
                              profile_F0=None, bootstrap=50, types=types, types_rule="RDM1", chain_name="three",
                              **SHORT)
    assert list(table.column("disorder")) == ["h", "three"]
    assert_columns_identical(table, csv)
    assert without_process_keys(table.metadata) == without_process_keys(meta)
    with pytest.raises(ValueError, match="types_rule 'RDM1': only with types or type_masses"):
        gr.exponent_table(chains=["h"], types_rule="RDM1", **SHORT)
    with pytest.raises(ValueError, match="quasi: not with `?types"):
        gr.exponent_table(chains=["h"], types=types, quasi="s2", **SHORT)


def _keywords(table, skip=()):
    """The keywords of a library parameter table (granular._core.X._parameters) that a function takes."""
    return [word for name, word, _ in table._parameters if name not in skip]


@pytest.mark.parametrize("function, tables", [
    (gr.spreading, [(gr._core.TransportCase, ("fit_begin", "fit_end")), (gr._core.ModeKick, ())]),
    (gr.transport, [(gr._core.TransportCase, ("fit_begin", "fit_end", "deviation_samples", "lyapunov_vectors",
                                              "covariant_vectors", "covariant_transient",
                                              *gr._core._spreading_output_parameters)),
                    # an ensemble draws its chains: no files, no one realization; s1's N/m stiffness: none
                    (gr._core.ChainChoices, ("config", "radii", "realization", "k0_n_per_m")), (gr._core.ModeKick, ()),
                    (gr._core._RunOptions, ())]),
    (gr.exponent_table, [(gr._core.TransportCase, ("fit_begin", "fit_end", "deviation_samples", "lyapunov_vectors",
                                                   "covariant_vectors", "covariant_transient",
                                                   *gr._core._spreading_output_parameters)),
                         (gr._core.ExponentChoices, ()),
                         (gr._core.ModeKick, ()), (gr._core._RunOptions, ())]),
])
def test_every_parameter_of_the_library_tables_is_a_documented_keyword(function, tables):
    """The library describes each choice once (parameter_table.hpp); the tools make their flags of it.
    A parameter added there must reach Python too: as a keyword, documented in the docstring."""
    taken = inspect.signature(function).parameters
    for table, skip in tables:
        for word in _keywords(table, skip):
            assert word in taken, f"{function.__name__} takes no keyword {word}"
            assert re.search(rf"(?<![\w-]){word}(?![\w-])", function.__doc__), \
                f"{function.__name__}'s docstring does not explain {word}"


@pytest.mark.parametrize("function", [gr.spreading, gr.transport, gr.exponent_table])
def test_the_run_keywords_and_their_defaults_are_the_library_table(function):
    """Every row of the library's tables over the case (transport_parameters(), and for granular.spreading
    spreading_output_parameters()) is a keyword of each kicked-run function, with the case's own C++ default: a row
    added in lib/ reaches Python with no line written here."""
    case = gr._core.TransportCase()
    taken = inspect.signature(function).parameters
    # site None: the centre; fit: a pair; forces_at None or a list of beads
    python_forms = {"site": None, "fit_begin": None, "fit_end": None, "forces_at": None}
    one_run = ("deviation_samples", "lyapunov_vectors", "covariant_vectors", "covariant_transient",
               *gr._core._spreading_output_parameters)
    for name, word, _ in gr._core.TransportCase._parameters:
        if not hasattr(case, name) or name in python_forms:
            continue
        if name in one_run and function is not gr.spreading:
            assert word not in taken, "an ensemble writes no deviation vector's file, spectrum nor one run's outputs"
            continue
        assert word in taken, f"{function.__name__} takes no keyword {word}"
        assert taken[word].kind == inspect.Parameter.KEYWORD_ONLY
        assert taken[word].default == getattr(case, name), f"{function.__name__}({word}=...) default"
    assert taken["site"].default is None
    assert taken["fit"].default == (case.fit_begin, case.fit_end)
    assert function is not gr.spreading or taken["forces_at"].default is None


def test_an_unknown_run_keyword_is_a_type_error_naming_it():
    with pytest.raises(TypeError, match="unexpected keyword argument 'fit_stp'"):
        gr.transport(fit_stp=1e-5)


def test_a_renamed_keyword_still_works_once_with_a_future_warning():
    """mode_khz (a mode kick's nearest frequency) is now near, as granular.spectrum's: the former keyword gives the
    same run and a FutureWarning naming the new one; both together are a TypeError."""
    chain = gr.anderson(N=51, seed=2)
    short = dict(T=1e-4, fit=(2e-5, 1e-4), samples=20)
    now = gr.spreading(chain, ic="mode", near=20, energy=1e-9, **short)
    with pytest.warns(FutureWarning, match="'mode_khz' is deprecated: use 'near'"):
        before = gr.spreading(chain, ic="mode", mode_khz=20, energy=1e-9, **short)
    np.testing.assert_array_equal(now["m2"], before["m2"])
    assert now["metadata"]["parameters"] == before["metadata"]["parameters"]
    with pytest.raises(TypeError, match="both 'mode_khz' and 'near'"):
        gr.spreading(chain, ic="mode", near=20, mode_khz=20, energy=1e-9, **short)
    assert "mode_khz" not in inspect.signature(gr.spreading).parameters
