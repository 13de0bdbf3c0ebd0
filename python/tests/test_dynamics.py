"""granular.spreading, granular.transport and granular.exponent_table: identical numbers to the
spreading and exponents tools on the same chains and seeds, and the conservation law the
integrator must keep."""
import json

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
    for key in ("t", "m2", "ipr", "energy_error"):
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
    mine = without_process_keys(run.metadata)
    assert mine == without_process_keys(meta)
    assert run.gamma["value"] == meta["gamma"] and run.eta["value"] == meta["eta"]


def test_velocity_kick_at_a_chosen_site_equals_the_spreading_tool(tools):
    csv, meta = tools.run("spreading", "--disorder", "RDM2", "--N", "151", "--F0", "0.5", "--ic", "velocity",
                          "--beta", "match", "--site", "60", "--integrator", "aba864", "--samples", "80", *SHORT_FLAGS,
                          output="vel")
    run = gr.spreading(gr.rdm2(N=151, F0=0.5), ic="velocity", beta="match", site=60, integrator="aba864", samples=80,
                       **SHORT)
    assert_identical(run.m2, csv["m2"])
    assert_identical(run.ipr, csv["ipr"])
    assert run.metadata["parameters"]["beta_m_s"] == meta["parameters"]["beta_m_s"] > 0


def test_energy_is_conserved_and_a_homogeneous_chain_spreads_ballistically():
    run = gr.spreading(gr.homogeneous(N=1001, F0=10), T=2e-3, fit=(5e-4, 2e-3), integrator="srkn14a")
    assert run.max_energy_error < 1e-8
    total = run.final_state["energy"].sum()
    assert total == pytest.approx(run.initial_energy, rel=1e-6)  # walls not reached: sum E_n is H
    assert not run.reached_walls
    assert run.gamma["value"] == pytest.approx(2.0, abs=0.05)  # SPEC §4: ballistic, m2 ~ t^2


def test_ensemble_equals_the_spreading_tool(tools):
    csv, meta = tools.run("spreading", "--disorder", "A", "--N", "201", "--realizations", "4", "--threads", "2",
                          "--profile", *SHORT_FLAGS, output="ens")
    t = gr.transport(disorder="A", N=201, realizations=4, threads=2, profile=True, **SHORT)
    for key in ("t", "m2", "ipr", "energy_error"):
        assert_identical(t[key], csv[key])
    sem = read_csv(tools.path("ens-sem.csv"))
    assert_identical(t.m2_se, sem["m2_se"])
    assert_identical(t.ipr_se, sem["ipr_se"])
    profile = read_csv(tools.path("ens-profile.csv"))
    assert_identical(t.profile["energy"], profile["energy"])
    assert_identical(t.profile["energy_se"], profile["energy_se"])
    mine, theirs = without_process_keys(t.metadata), without_process_keys(meta)
    assert mine.pop("version") == theirs.pop("version")
    assert mine == theirs


def test_ensemble_mean_is_the_mean_of_the_single_runs():
    t = gr.transport(disorder="RDM1", N=121, realizations=3, seed=2, **SHORT)
    runs = [gr.spreading(gr.rdm1(N=121, seed=2, realization=r), **SHORT) for r in range(3)]
    np.testing.assert_allclose(t.m2, np.mean([r.m2 for r in runs], axis=0), rtol=1e-14)
    np.testing.assert_allclose(t.ipr, np.mean([r.ipr for r in runs], axis=0), rtol=1e-14)


def test_exponent_table_equals_the_exponents_tool(tools):
    flags = ["--chains", "h,A", "--F0", "10,0", "--ic", "displacement,velocity", "--N", "151", "--realizations", "3",
             "--samples", "60", "--profile-F0", "10", "--profile-realizations", "2", *SHORT_FLAGS, "--quiet"]
    csv, meta = tools.run("exponents", *flags, output="exp")
    table = gr.exponent_table(chains=["h", "A"], F0=[10, 0], ic=["displacement", "velocity"], N=151, realizations=3,
                              samples=60, profile_F0=[10], profile_realizations=2, **SHORT)
    assert [r["disorder"] for r in table.table] == csv["disorder"]
    for key in ("F0", "gamma", "gamma_err", "eta", "eta_err", "worst_deviation_m2", "max_energy_error",
                "realizations"):
        assert_identical(table.column(key), csv[key])
    assert [str(v).lower() for v in table.column("power_law_m2")] == csv["power_law_m2"]
    curves = read_csv(tools.path("exp-curves.csv"))
    assert_identical(np.concatenate([c["m2"] for c in table.curves]), curves["m2"])
    profiles = read_csv(tools.path("exp-profiles.csv"))
    assert_identical(np.concatenate([p["energy"] for p in table.profiles]), profiles["energy"])
    assert table.metadata["cases"] == meta["cases"]
    assert "| F0 [N] | h | A |" in table.markdown("gamma", "velocity")
