"""granular.crystal: its keywords are the library's crystal_parameters() rows with CrystalCase's C++ defaults, and
it returns what the crystal tool writes."""
import inspect
import subprocess
import sys

import numpy as np
import pytest

import granular as gr
from granular import _core


def test_signature_is_the_table_with_its_cpp_defaults():
    rows = _core.CrystalCase._parameters
    defaults = _core.CrystalCase()
    signature = inspect.signature(gr.crystal).parameters
    assert [keyword for _, keyword, _ in rows] == list(signature)
    for name, keyword, help_text in rows:
        value = getattr(defaults, name)
        expected = None if value == "" or (isinstance(value, float) and np.isnan(value)) else value
        assert signature[keyword].default == expected, keyword
        assert signature[keyword].kind == inspect.Parameter.KEYWORD_ONLY
        assert help_text.split(" (")[0][:30] in gr.crystal.__doc__, keyword


def test_every_mode_of_a_small_crystal_and_its_displacements():
    r = gr.crystal(lattice="hexagonal", Lx=6, Ly=6, width=0.2, vectors=True)
    assert r.method == "lapack"
    assert r.freq_khz.shape == (72,) and np.all(np.diff(r.freq_khz) >= 0) and r.freq_khz[0] > 0
    np.testing.assert_allclose(r.omega2, (2 * np.pi * 1e3 * r.freq_khz) ** 2, rtol=1e-12)
    assert r.vectors.shape == (72, 36, 2)
    # the IPR is the displacements' (docs/crystals.md): sum |u_b|^4 / (sum |u_b|^2)^2
    u2 = (r.vectors ** 2).sum(axis=2)
    np.testing.assert_allclose(r.ipr, (u2 ** 2).sum(axis=1) / u2.sum(axis=1) ** 2, rtol=1e-12)
    assert r.imbalance <= 1e-12
    assert r.metadata["parameters"]["width"] == 0.2


def test_nearest_modes_are_among_every_mode():
    every = gr.crystal(lattice="hexagonal", Lx=8, Ly=8, width=0.3, seed=4)
    target = float(every.freq_khz[64])
    near = gr.crystal(lattice="hexagonal", Lx=8, Ly=8, width=0.3, seed=4, near=target, count=6)
    assert near.method == "arpack" and near.freq_khz.shape == (6,)
    for f in near.freq_khz:
        assert np.min(np.abs(every.freq_khz - f)) <= 1e-10 * f


@pytest.mark.parametrize("keywords, name", [
    ({"Lx": 1}, "Lx"), ({"lattice": "cubic"}, "lattice"), ({"count": 3}, "count"), ({"width": 1.5}, "width"),
    ({"method": "slepc"}, "method"), ({"boundary": "periodic", "strain": 0.01}, "packing"),
])
def test_bad_keywords_are_value_errors_naming_them(keywords, name):
    with pytest.raises(ValueError, match=name):
        gr.crystal(**keywords)


def test_an_unknown_keyword_is_a_type_error():
    with pytest.raises(TypeError, match="Lz"):
        gr.crystal(Lz=3)


def test_the_tool_writes_the_same_modes(tools):
    csv, meta = tools.run("crystal", "--lattice", "square", "--Lx", "5", "--Ly", "7", "--disorder", "radius",
                          "--width", "0.001", "--F0", "1000", "--quiet")
    r = gr.crystal(lattice="square", Lx=5, Ly=7, disorder="radius", width=0.001, F0=1000.0)
    np.testing.assert_array_equal(csv["freq_khz"], r.freq_khz)
    np.testing.assert_array_equal(csv["ipr"], r.ipr)
    assert meta["parameters"] == r.metadata["parameters"]


def test_ipr_map_signature_is_the_crystals_rows_then_its_own():
    crystal_rows = [k for _, k, _ in _core.CrystalCase._parameters]
    names = list(inspect.signature(gr.crystal_ipr_map).parameters)
    run = ["threads", "checkpoint", "resume", "resume_other_version", "fresh", "progress"]  # how, after what
    assert names[-9:] == ["widths", "realizations", "bin_hz"] + run
    assert all(n in crystal_rows for n in names[:-9])
    assert inspect.signature(gr.crystal_ipr_map).parameters["widths"].default == list(_core.CrystalIprMapConfig().widths)


def test_ipr_map_cells_count_every_mode_and_the_perfect_row_is_the_crystals():
    m = gr.crystal_ipr_map(lattice="hexagonal", Lx=6, Ly=6, widths=[0.0, 0.8], realizations=3, bin_hz=2000.0)
    assert m.modes.shape == m.ipr.shape == m.ratio.shape
    assert (m.modes.sum(axis=1) == 3 * 72).all()
    perfect = gr.crystal(lattice="hexagonal", Lx=6, Ly=6)
    bins = np.minimum((np.maximum(perfect.freq_khz, 0) / 2).astype(int), m.modes.shape[1] - 1)
    for b in np.unique(bins):
        np.testing.assert_allclose(m.ipr[0, b], perfect.ipr[bins == b].mean(), rtol=1e-12)
    with pytest.raises(ValueError, match="widths"):
        gr.crystal_ipr_map(widths=[1.5])


def test_ipr_map_of_the_modes_nearest_a_frequency_counts_count_per_crystal():
    m = gr.crystal_ipr_map(lattice="hexagonal", Lx=8, Ly=8, widths=[0.3], realizations=2, bin_hz=1000.0,
                           near=10.0, count=12)
    assert m.modes.sum() == 2 * 12
    filled = np.flatnonzero(m.modes[0])
    assert 8 <= filled.min() and filled.max() <= 11  # the 12 modes nearest 10 kHz sit near it
    assert m.metadata["parameters"]["near"] == 10.0
    with pytest.raises(ValueError, match="count"):
        gr.crystal_ipr_map(Lx=4, Ly=4, near=5.0, count=32)


def test_ipr_map_equals_the_crystal_ipr_map_tool_and_its_figure_reads_the_csv(tools):
    args = dict(lattice="hexagonal", Lx=6, Ly=6, widths=[0.0, 0.7], realizations=2, bin_hz=2500.0)
    m = gr.crystal_ipr_map(**args, threads=1)
    csv, meta = tools.run("crystal-ipr-map", "--lattice", "hexagonal", "--Lx", "6", "--Ly", "6", "--widths", "0,0.7",
                          "--realizations", "2", "--bin-hz", "2500", "--quiet")
    assert meta["parameters"] == m.metadata["parameters"]
    some = m.modes.ravel() > 0  # the tool writes each width's bins up to its own top
    np.testing.assert_array_equal(csv["ipr"][csv["modes"] > 0], m.ipr.ravel()[some])
    np.testing.assert_array_equal(csv["modes"][csv["modes"] > 0], m.modes.ravel()[some])
    fig = gr.plot.crystal_ipr_map(tools.path("out.csv"))
    assert len(fig.axes) == 2
    done = subprocess.run([sys.executable, "-m", "granular.plot", "crystal-ipr-map", str(tools.path("out.csv"))],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert tools.path("out.png").exists()


def test_ipr_map_resumes_from_its_checkpoint_to_the_same_map(tmp_path):
    args = dict(lattice="hexagonal", Lx=6, Ly=6, widths=[0.3], realizations=3, bin_hz=3000.0)
    whole = gr.crystal_ipr_map(**args)
    log = tmp_path / "map.checkpoint"
    again = gr.crystal_ipr_map(**args, checkpoint=log)
    assert not log.exists()  # removed once the map is complete
    np.testing.assert_array_equal(again.ipr, whole.ipr)
    with pytest.raises(ValueError, match="fresh"):
        gr.crystal_ipr_map(**args, checkpoint=log, resume=True, fresh=True)


def test_window_by_spectrum_slicing_is_every_dense_mode_inside_it():
    every = gr.crystal(lattice="hexagonal", Lx=10, Ly=10, width=0.4)
    lo, hi = (every.freq_khz[60] + every.freq_khz[61]) / 2, (every.freq_khz[90] + every.freq_khz[91]) / 2
    sliced = gr.crystal(lattice="hexagonal", Lx=10, Ly=10, width=0.4, window=(lo, hi))
    assert sliced.method == "slepc-slicing"
    np.testing.assert_allclose(sliced.freq_khz, every.freq_khz[61:91], rtol=1e-10)
    np.testing.assert_allclose(sliced.ipr, every.ipr[61:91], rtol=1e-8)
    with pytest.raises(ValueError, match="window"):
        gr.crystal(near=10.0, window=(1.0, 2.0))
