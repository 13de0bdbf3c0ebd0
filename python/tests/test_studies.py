"""granular.ipr_map and granular.correlations: identical numbers to the ipr-map and correlations
tools on the same grid and seed, the tools' metadata, and independence of the thread count."""
import numpy as np
import pytest

import granular as gr
from conftest import assert_identical


def test_ipr_map_equals_the_tool(tools):
    csv, meta = tools.run("ipr-map", "--disorder", "RDM1", "--xi", "0.3:0.5:0.1", "--q", "0.2,0.7", "--N", "40",
                          "--realizations", "6", "--seed", "5", "--quiet")
    grid = gr.ipr_map(disorder="RDM1", xi="0.3:0.5:0.1", q=[0.2, 0.7], N=40, realizations=6, seed=5, threads=2)
    rows = grid.rows()
    for key in ("q", "xi", "mode", "freq_khz", "ipr"):
        assert_identical(rows[key], csv[key])
    assert grid.freq_khz.shape == grid.ipr.shape == (2, 3, 40)
    assert_identical(grid.ipr.ravel(), csv["ipr"])
    assert_identical(grid.xi, [0.3, 0.4, 0.5])
    assert grid.metadata["parameters"] == meta["parameters"]
    assert grid.metadata["averaging"] == meta["averaging"] == "mode"


def test_ipr_map_lapack_solver_equals_the_tool(tools):
    csv, meta = tools.run("ipr-map", "--xi", "0.2,0.9", "--q", "0.5", "--N", "25", "--realizations", "4",
                          "--solver", "lapack-steqr", "--quiet")
    grid = gr.ipr_map(xi=(0.2, 0.9), q=0.5, N=25, realizations=4, solver="lapack-steqr")
    assert_identical(grid.rows()["ipr"], csv["ipr"])
    assert grid.metadata["parameters"] == meta["parameters"]


@pytest.mark.parametrize("keywords, flags", [
    ({"types": "4.76e-3:0.6,3e-3:0.4"}, ["--types", "4.76e-3:0.6,3e-3:0.4"]),
    ({"type_masses": "4e-3:0.5,1e-3:0.5", "disorder": "RDM1"}, ["--type-masses", "4e-3:0.5,1e-3:0.5", "--disorder",
                                                                  "RDM1"]),
    ({"polydisperse": "uniform:4e-3:5e-3", "walls": "sphere"}, ["--polydisperse", "uniform:4e-3:5e-3", "--walls",
                                                                "sphere"]),
])
def test_ipr_map_takes_every_chain_kind_of_its_tool(tools, keywords, flags):
    """k bead types, k masses and polydisperse radii (one cell, q = xi = NaN, realizations are draws), as the
    ipr-map tool's --types, --type-masses and --polydisperse: the same numbers and parameters."""
    csv, meta = tools.run("ipr-map", "--N", "30", "--realizations", "4", "--seed", "3", *flags, "--quiet")
    grid = gr.ipr_map(N=30, realizations=4, seed=3, **keywords)
    rows = grid.rows()
    for key in ("mode", "freq_khz", "ipr"):
        assert_identical(rows[key], csv[key])
    assert np.isnan(grid.q).all() and np.isnan(grid.xi).all()
    assert grid.metadata["parameters"] == meta["parameters"]
    with pytest.raises(ValueError, match="polydisperse"):  # one kind of chain at a time, named
        gr.ipr_map(N=30, types="4.76e-3:0.6,3e-3:0.4", polydisperse="uniform:4e-3:5e-3")


def test_ipr_map_solver_rules_are_the_tools():
    with pytest.raises(ValueError, match="solver 'lapack-magic': expected fast, lapack or lapack-"):
        gr.ipr_map(N=20, realizations=2, solver="lapack-magic")
    with pytest.raises(ValueError, match="method: only with near/count or window"):
        gr.ipr_map(N=20, realizations=2, method="bisect")
    with pytest.raises(ValueError, match="method fast: computes every mode"):
        gr.ipr_map(N=20, realizations=2, near=5, count=2, method="fast")


def test_partial_ipr_map_equals_the_tool(tools):
    csv, meta = tools.run("ipr-map", "--disorder", "A", "--xi", "0.5", "--q", "0.5", "--N", "300",
                          "--realizations", "3", "--near", "15", "--count", "4", "--method", "bisect", "--quiet")
    grid = gr.ipr_map(disorder="A", xi=0.5, q=0.5, N=300, realizations=3, near=15, count=4, method="bisect")
    rows = grid.rows()
    for key in ("q", "xi", "realization", "mode", "freq_khz", "ipr"):
        assert_identical(rows[key], csv[key])
    assert grid.selection and grid.ipr.shape == (12,)
    assert grid.metadata["selection"] == meta["selection"]


def test_ipr_map_is_the_mean_of_the_single_chain_spectra():
    grid = gr.ipr_map(disorder="RDM2", xi=[0.4], q=[0.3], N=30, realizations=5, seed=2, solver="lapack")
    spectra = [gr.spectrum(gr.rdm2(N=30, q=0.3, xi=0.4, seed=2, realization=r)) for r in range(5)]
    np.testing.assert_allclose(grid.ipr[0, 0], np.mean([s.ipr for s in spectra], axis=0), rtol=1e-14)
    np.testing.assert_allclose(grid.freq_khz[0, 0], np.mean([s.freq_khz for s in spectra], axis=0), rtol=1e-14)


def test_ipr_map_does_not_depend_on_the_thread_count():
    a = gr.ipr_map(xi="0.1:0.3", q=0.5, N=50, realizations=9, threads=1)
    b = gr.ipr_map(xi="0.1:0.3", q=0.5, N=50, realizations=9, threads=2)
    assert_identical(a.ipr, b.ipr)
    assert_identical(a.freq_khz, b.freq_khz)


def test_correlations_equal_the_tool(tools):
    csv, meta = tools.run("correlations", "--disorder", "RDM2", "--q", "0.8", "--N", "60", "--realizations", "30",
                          "--seed", "4", "--max-distance", "6")
    c = gr.correlations(disorder="RDM2", q=0.8, N=60, realizations=30, seed=4, max_distance=6)
    assert_identical(c.distance, csv["distance"])
    assert_identical(c.rho_mean, csv["rho_mean"])
    assert_identical(c.rho_std, csv["rho_std"])
    assert_identical(c.rho_theory, csv["rho_theory"])
    assert c.metadata["parameters"] == meta["parameters"]
    assert c.used == meta["realizations_used"] == 30


def test_correlation_ensemble_approaches_the_infinite_chain_formula():
    c = gr.correlations(disorder="RDM1", q=0.5, N=2000, realizations=20, max_distance=4)
    np.testing.assert_allclose(c.rho_mean, c.rho_theory, atol=5 * c.rho_std.max() / np.sqrt(20) + 1e-12)
    assert c.rho_theory[1] == pytest.approx(0.5)  # RDM1 at q = 1/2: the partner in the dimer


def test_progress_bar_is_drawn_on_stderr(capfd):
    gr.ipr_map(xi="0.5:0.6", q=0.5, N=20, realizations=4, progress=True)
    err = capfd.readouterr().err
    assert "ipr_map:" in err and "44/44" in err and "100%" in err
    gr.ipr_map(xi="0.5:0.6", q=0.5, N=20, realizations=4)
    assert capfd.readouterr().err == ""


def test_localization_equals_the_tool_for_a_streamed_chain_and_a_types_file(tools, data_dir):
    csv, meta = tools.run("localization", "--disorder", "RDM1", "--N", "2e5", "--f", "1:40:0.5", "--segments", "16",
                          "--seed", "3", "--quiet", output="loc")
    scan = gr.localization(disorder="RDM1", N=2e5, f="1:40:0.5", segments=16, seed=3)
    for key in ("freq_khz", "lyapunov", "lyapunov_err", "loc_length", "idos", "dos"):
        assert_identical(getattr(scan, key), csv[key])
    assert_identical(scan.resolved.astype(int), np.asarray(csv["resolved"], int))
    assert scan.metadata["resolved_rule"] == meta["resolved_rule"]
    assert scan.metadata["chain"] == meta["chain"]
    assert scan.metadata["parameters"] == meta["parameters"]
    assert scan.metadata["band_edges_khz"] == meta["band_edges_khz"]
    types_file = data_dir / "examples" / "diatomic-10.types"
    csv, _ = tools.run("localization", "--config", types_file, "--f", "0:40:1", "--segments", "2", "--quiet",
                       output="loc2")
    scan = gr.localization(gr.from_types(gr.read_types(str(types_file))), f="0:40:1", segments=2)
    assert_identical(scan.lyapunov, csv["lyapunov"])
    assert_identical(scan.idos, csv["idos"])


def test_localization_flags_unresolved_lengths():
    scan = gr.localization(disorder="A", N=1e5, f=[0, 0.5, 1, 15, 20])
    assert scan.resolved.dtype == bool
    assert list(scan.resolved) == [False, False, False, True, True]
    assert "ln(N)/N" in scan.metadata["resolved_rule"]
    one = gr.localization(disorder="A", N=1e5, f=[10])
    assert np.isfinite(one.dos[0]) and one.dos[0] > 0


def test_localization_node_counts_are_the_spectrum_and_streaming_gives_the_built_chain():
    chain = gr.anderson(N=300, seed=2, realization=1)
    modes = gr.spectrum(chain)
    f = np.sort(np.concatenate([(modes.freq_khz[:-1] + modes.freq_khz[1:]) / 2, [modes.freq_khz[-1] + 1]]))
    built = gr.localization(chain, f=f)
    assert_identical(built.modes_below, np.arange(1, 301))  # Dean's method: exactly one mode between midpoints
    streamed = gr.localization(N=300, seed=2, realization=1, f=f)
    assert_identical(streamed.lyapunov, built.lyapunov)


def test_frequency_binned_ipr_map_equals_the_tool(tools):
    csv, meta = tools.run("ipr-map", "--disorder", "RDM2", "--xi", "0.5", "--q", "0.5", "--N", "50",
                          "--realizations", "5", "--bin-khz", "2", "--quiet")
    grid = gr.ipr_map(disorder="RDM2", xi=0.5, q=0.5, N=50, realizations=5, bin_khz=2.0)
    rows = grid.rows()
    for key in ("q", "xi", "freq_lo_khz", "freq_hi_khz", "modes", "ipr"):
        assert_identical(rows[key], csv[key])
    assert rows["modes"].sum() == 5 * 50  # every mode of every realization in one bin
    assert grid.metadata["averaging"] == meta["averaging"] == "frequency-bin"
    assert grid.metadata["bin_khz"] == meta["bin_khz"]


PROCESS_KEYS = ("tool", "function", "command", "started_utc", "wall_time_s", "output", "vectors")


def without_process_keys(meta):
    """A tool's JSON or a result's metadata minus what only a process has (name, command line, clock, files)."""
    return {k: v for k, v in meta.items() if k not in PROCESS_KEYS}


@pytest.mark.parametrize("args, keywords", [
    (["--xi", "0.5", "--q", "0.5", "--N", "30", "--realizations", "3"], dict(xi=0.5, q=0.5, N=30, realizations=3)),
    (["--xi", "0.5", "--q", "0.5", "--N", "30", "--realizations", "3", "--bin-khz", "2"],
     dict(xi=0.5, q=0.5, N=30, realizations=3, bin_khz=2.0)),
    (["--xi", "0.5", "--q", "0.5", "--N", "60", "--realizations", "2", "--window", "10:20", "--method", "bisect"],
     dict(xi=0.5, q=0.5, N=60, realizations=2, window=(10, 20), method="bisect")),
])
def test_ipr_map_metadata_is_the_tools_json(tools, args, keywords):
    """One description in the library (granular::describe_ipr_map): every entry equal, not a chosen few."""
    _, meta = tools.run("ipr-map", *args, "--threads", "1", "--quiet")
    grid = gr.ipr_map(**keywords, threads=1)
    assert without_process_keys(grid.metadata) == without_process_keys(meta)


def test_correlations_and_localization_metadata_are_the_tools_json(tools):
    _, meta = tools.run("correlations", "--N", "40", "--realizations", "5", "--max-distance", "3", "--threads", "1",
                        "--quiet")
    c = gr.correlations(N=40, realizations=5, max_distance=3, threads=1)
    assert without_process_keys(c.metadata) == without_process_keys(meta)
    _, meta = tools.run("localization", "--N", "1000", "--f", "1:3", "--segments", "4", "--threads", "1", "--quiet",
                        output="loc")
    scan = gr.localization(N=1000, f="1:3", segments=4, threads=1)
    assert without_process_keys(scan.metadata) == without_process_keys(meta)


# One table, every front end: the localization tool's chain options and granular.localization's chain keywords
# are both made of the library's ChainChoices table, so every chain kind the tool takes, Python takes, with
# the same defaults (the library's localization_chain) and the same numbers.
def test_localization_signature_is_made_from_the_chain_table():
    import inspect
    signature = inspect.signature(gr.localization)
    defaults = gr._core._localization_chain()
    rows = [(name, keyword) for name, keyword, _ in type(defaults)._parameters]
    assert rows, "the chain table reached Python empty"
    for name, keyword in rows:
        assert keyword in signature.parameters, keyword
        parameter = signature.parameters[keyword]
        assert parameter.kind == inspect.Parameter.KEYWORD_ONLY
        value = getattr(defaults, name)
        assert parameter.default == (None if value == "" else value), keyword
        assert f"\n    {keyword}: " in gr.localization.__doc__, keyword
    assert signature.parameters["N"].default == 1000000  # the job's own default, made in C++
    with pytest.raises(TypeError, match="'Nbeads'"):
        gr.localization(Nbeads=10)
    with pytest.raises(ValueError, match="^N: not with a given chain"):
        gr.localization(gr.anderson(N=10), N=20)


@pytest.mark.parametrize("chain_flags, keywords", [
    (["--types", "4.76e-3:0.5,2.38e-3:0.3,3.5e-3:0.2", "--N", "3000"],
     dict(types="4.76e-3:0.5,2.38e-3:0.3,3.5e-3:0.2", N=3000)),
    (["--polydisperse", "uniform:2.4e-3:4.8e-3", "--N", "3000", "--seed", "4"],
     dict(polydisperse="uniform:2.4e-3:4.8e-3", N=3000, seed=4)),
    (["--type-masses", "4.5e-4:0.5,5.6e-5:0.5", "--N", "3000", "--disorder", "RDM2"],
     dict(type_masses="4.5e-4:0.5,5.6e-5:0.5", N=3000, disorder="RDM2")),
    (["--walls", "sphere", "--N", "3000", "--xi", "0.7"], dict(walls="sphere", N=3000, xi=0.7)),
])
def test_localization_takes_every_chain_kind_of_the_tool(tools, chain_flags, keywords):
    csv, meta = tools.run("localization", *chain_flags, "--f", "1:30:1", "--segments", "4", "--quiet", output="kind")
    scan = gr.localization(f="1:30:1", segments=4, **keywords)
    for key in ("lyapunov", "lyapunov_err", "idos", "dos"):
        assert_identical(getattr(scan, key), csv[key])
    assert scan.metadata["chain"] == meta["chain"]
    assert scan.metadata["parameters"] == meta["parameters"]


def test_localization_takes_a_radii_file_as_the_tool(tools, tmp_path):
    radii = tmp_path / "chain.radii"
    radii.write_text("".join(f"{r}\n" for r in [4.76e-3, 2.38e-3, 3.0e-3] * 40))
    csv, meta = tools.run("localization", "--radii", radii, "--f", "1:30:1", "--segments", "2", "--quiet",
                          output="radii")
    scan = gr.localization(radii=str(radii), f="1:30:1", segments=2)
    assert_identical(scan.lyapunov, csv["lyapunov"])
    assert scan.metadata["chain"] == meta["chain"]


@pytest.mark.parametrize("keywords, flags", [
    ({"types": "4.76e-3:0.5,3e-3:0.3,2e-3:0.2"}, ["--types", "4.76e-3:0.5,3e-3:0.3,2e-3:0.2"]),
    ({"polydisperse": "normal:4.5e-3:3e-4:3e-3", "disorder": "RDM2"},
     ["--polydisperse", "normal:4.5e-3:3e-4:3e-3", "--disorder", "RDM2"]),
])
def test_correlations_take_every_chain_kind_of_their_tool(tools, keywords, flags):
    """k types and polydisperse radii (rho(d) of the bead masses), as the correlations tool's --types and
    --polydisperse: the same numbers and parameters."""
    csv, meta = tools.run("correlations", "--N", "60", "--realizations", "5", "--seed", "2", "--max-distance", "6",
                          *flags, "--quiet")
    result = gr.correlations(N=60, realizations=5, seed=2, max_distance=6, **keywords)
    for key in ("rho_mean", "rho_std"):
        assert_identical(getattr(result, key), csv[key])
    assert result.metadata["parameters"] == meta["parameters"]
