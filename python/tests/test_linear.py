"""granular.spectrum, SpectrumSolver, DynamicalMatrix and band_edges: the same numbers as the
spectrum tool on the same chain (parsed from its CSV, compared exactly), and the physics checks
an independent method gives (dense eigen-solver, the band edges of ordered chains)."""
import inspect
import re

import numpy as np
import pytest

import granular as gr
from conftest import assert_identical

CHAIN = ["--disorder", "A", "--xi", "0.5", "--q", "0.5", "--N", "100", "--seed", "3", "--realization", "2"]


def chain():
    return gr.anderson(N=100, q=0.5, xi=0.5, seed=3, realization=2)


def compare(result, csv):
    assert_identical(result.mode, csv["mode"])
    assert_identical(result.freq_khz, csv["freq_khz"])
    assert_identical(result.ipr, csv["ipr"])


@pytest.mark.parametrize("method", ["lapack", "fast"])
def test_every_mode_equals_the_spectrum_tool(tools, method):
    csv, meta = tools.run("spectrum", *CHAIN, "--method", method)
    result = gr.spectrum(chain(), method=method)
    compare(result, csv)
    # the metadata the tool writes, minus what only a process has (command line, clock, file names)
    mine = result.metadata
    for key in ("chain", "method", "solver", "band_edges_khz", "version"):
        assert mine[key] == meta[key], key


@pytest.mark.parametrize("method", ["lapack", "bisect", "arpack", "slepc"])
def test_nearest_modes_equal_the_spectrum_tool(tools, method):
    csv, meta = tools.run("spectrum", *CHAIN, "--near", "15", "--count", "7", "--method", method)
    result = gr.spectrum(chain(), near=15.0, count=7, method=method)
    compare(result, csv)
    assert result.metadata["selection"] == meta["selection"] == {"near_khz": 15.0, "count": 7}
    assert result.metadata["solver"] == meta["solver"]


def test_window_equals_the_spectrum_tool(tools):
    csv, meta = tools.run("spectrum", *CHAIN, "--window", "10:20", "--method", "bisect")
    result = gr.spectrum(chain(), window=(10, 20), method="bisect")
    compare(result, csv)
    assert result.metadata["selection"] == meta["selection"]
    empty = gr.spectrum(chain(), window=(100, 101), method="bisect")
    assert len(empty) == 0 and empty.freq_khz.shape == (0,)


def test_config_and_radii_files_equal_the_spectrum_tool(tools, data_dir):
    types_file = data_dir / "examples" / "diatomic-10.types"
    csv, _ = tools.run("spectrum", "--config", types_file, "--xi", "0.5")
    compare(gr.spectrum(gr.from_types(gr.read_types(str(types_file)), xi=0.5)), csv)
    radii_file = data_dir / "examples" / "single-impurity-11.radii"
    csv, _ = tools.run("spectrum", "--radii", radii_file, "--F0", "2")
    compare(gr.spectrum(gr.from_radii(gr.read_radii(str(radii_file)), F0=2.0)), csv)


def test_vectors_are_unit_eigenvectors_of_the_matrix_in_fortran_order():
    c = chain()
    d = gr.dynamical_matrix(c)
    s = gr.spectrum(d, vectors=True)
    w = s.vectors
    assert w.shape == (100, 100) and w.flags.f_contiguous and not w.flags.writeable
    dense = np.diag(d.diagonal) + np.diag(d.off_diagonal, 1) + np.diag(d.off_diagonal, -1)
    scale = np.abs(dense).max()
    assert np.abs(dense @ w - w * s.omega2).max() < 1e-12 * scale
    assert np.abs(w.T @ w - np.eye(100)).max() < 1e-12
    # eigenvalues as an independent dense solver gives them
    np.testing.assert_allclose(np.sort(np.linalg.eigvalsh(dense)), s.omega2, rtol=1e-10, atol=1e-12 * scale)
    # displacement IPR from v = w m^-1/2
    v = s.displacements()
    assert_identical(v, w * d.inverse_sqrt_mass[:, None])
    np.testing.assert_allclose((v**4).sum(0) / (v**2).sum(0) ** 2, s.ipr, rtol=1e-12)
    assert_identical(gr.frequency_khz(s.omega2), s.freq_khz)
    # the arrays of a spectrum outlive the Python object that made them
    freq = gr.spectrum(c).freq_khz
    assert freq.shape == (100,) and freq.base is not None


def test_spectrum_solver_gives_what_spectrum_gives():
    solver = gr.SpectrumSolver(method="bisect")
    for seed in range(3):
        c = gr.rdm2(N=60, seed=seed)
        a = solver.solve(c, near=20.0, count=5)
        b = gr.spectrum(c, near=20.0, count=5, method="bisect")
        assert_identical(a.freq_khz, b.freq_khz)
        assert_identical(a.ipr, b.ipr)


@pytest.mark.parametrize("function", [gr.spectrum, gr.SpectrumSolver.solve, gr.ipr_map])
def test_every_mode_selection_parameter_is_a_documented_keyword(function):
    """The library describes the choice of modes once (mode_selection_parameters); the spectrum and ipr-map tools
    make their flags of it, and each of its parameters is a keyword here, explained in the docstring."""
    taken = inspect.signature(function).parameters
    assert len(gr._core.ModeSelectionChoices._parameters) == 3
    for _, word, _ in gr._core.ModeSelectionChoices._parameters:
        assert word in taken, f"{function.__name__} takes no keyword {word}"
        assert re.search(rf"(?<![\w-]){word}(?![\w-])", function.__doc__), \
            f"{function.__name__}'s docstring does not explain {word}"


def test_a_matrix_of_ones_own_from_any_array_like():
    n = 50
    # the monatomic chain with fixed ends: omega_k^2 = 4 sin^2(k pi / 2(n+1)) for D = tridiag(-1, 2, -1)
    d = gr.DynamicalMatrix(np.full(n, 2.0), [-1.0] * (n - 1))
    s = gr.spectrum(d)
    k = np.arange(1, n + 1)
    np.testing.assert_allclose(s.omega2, 4 * np.sin(k * np.pi / (2 * (n + 1))) ** 2, atol=1e-13)
    # plane waves sin(k n pi/(n+1)): IPR 3/(2(n+1))
    np.testing.assert_allclose(s.ipr, 1.5 / (n + 1), rtol=1e-10)
    strided = np.repeat(np.full(n, 2.0), 3)[::3]
    assert_identical(gr.spectrum(gr.DynamicalMatrix(strided, np.full(n - 1, -1.0, dtype=np.float32))).omega2,
                     s.omega2)


def test_band_edges_bound_the_spectrum_of_a_long_diatomic_chain():
    e = gr.band_edges(xi=0.5, F0=10.0)
    assert e.as_dict() == {"f1": e.f1, "f2": e.f2, "fb1": e.fb1, "fb2": e.fb2, "fb3": e.fb3}
    s = gr.spectrum(gr.diatomic(N=2000, xi=0.5, F0=10.0), method="fast")
    f = s.freq_khz
    bulk = s.ipr < 0.01  # surface modes of the flat walls are localized (README: Walls)
    acoustic, optical = f[bulk & (f < e.fb1 * 1.001)], f[bulk & (f > e.fb2 * 0.999)]
    assert acoustic.max() == pytest.approx(e.fb1, rel=1e-4)
    assert optical.min() == pytest.approx(e.fb2, rel=1e-4)
    assert optical.max() == pytest.approx(e.fb3, rel=1e-4)
    assert not np.any(bulk & (f > e.fb1 * 1.001) & (f < e.fb2 * 0.999))  # the gap
    mono = gr.spectrum(gr.homogeneous(N=2000, F0=10.0), method="fast").freq_khz
    assert mono.max() == pytest.approx(e.f1, rel=1e-5)


def test_cluster_flags_are_exposed_and_match_the_tool(tools):
    spec = gr.spectrum(gr.anderson(N=100, xi=0.1, seed=1))
    assert spec.clustered.dtype == bool and spec.clustered.shape == (100,)
    csv, meta = tools.run("spectrum", "--disorder", "A", "--N", "100", "--xi", "0.1", "--seed", "1", "--clusters",
                          output="c.csv")
    assert list(spec.clustered.astype(int)) == list(csv["clustered"].astype(int))
    assert meta["clustered"]["modes"] == int(spec.clustered.sum())


@pytest.mark.parametrize("selection, keywords", [
    ([], {}), (["--near", "15", "--count", "7", "--method", "bisect"], dict(near=15.0, count=7, method="bisect")),
    (["--window", "10:20", "--method", "bisect"], dict(window=(10, 20), method="bisect"))])
def test_metadata_is_the_spectrum_tools_json(tools, selection, keywords):
    """One description in the library (granular::describe_spectrum): every entry equal, not a chosen few."""
    _, meta = tools.run("spectrum", *CHAIN, *selection, "--quiet")
    result = gr.spectrum(chain(), **keywords)
    process = ("tool", "function", "command", "started_utc", "wall_time_s", "output", "vectors")
    assert {k: v for k, v in result.metadata.items() if k not in process} == \
        {k: v for k, v in meta.items() if k not in process}


@pytest.mark.parametrize("function", [gr.spectrum, gr.SpectrumSolver.__init__])
def test_solver_keywords_are_the_spectrum_table_with_its_cpp_defaults(function):
    """spectrum's and SpectrumSolver's solver keywords are the rows of spectrum_parameters(), with SpectrumConfig's
    own defaults and help (the spectrum tool's --method, --driver, --tolerance, --subspace, --lanes)."""
    from granular import _core
    defaults = _core.SpectrumConfig()
    signature = inspect.signature(function).parameters
    rows = _core.SpectrumConfig._parameters
    assert [keyword for _, keyword, _ in rows] == [k for k in signature if k in {r[1] for r in rows}]
    for name, keyword, help_text in rows:
        assert signature[keyword].default == getattr(defaults, name), keyword
        assert signature[keyword].kind == inspect.Parameter.KEYWORD_ONLY
        assert help_text[:30] in function.__doc__, keyword
    with pytest.raises(TypeError, match="solver_kind"):
        gr.spectrum(gr.anderson(N=10), solver_kind=1)
