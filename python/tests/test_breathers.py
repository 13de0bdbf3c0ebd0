"""granular.breathers: the same branch as the breathers tool on the same chain (to the last digit), and its
result's shapes and symplectic multipliers."""
import inspect
import math

import numpy as np
import pytest

import granular as gr
from conftest import assert_identical


def test_breathers_equals_the_tool(tools, tmp_path):
    types = [2 if i % 2 == 0 else 1 for i in range(21)]
    config = tmp_path / "diatomic.txt"
    config.write_text("\n".join(map(str, types)) + "\n")
    edge = gr.band_edges(xi=0.5).fb2  # kHz: the optical band's lower edge
    csv, meta = tools.run("breathers", "--config", str(config), "--xi", "0.5", "--near", repr(edge),
                          "--max-points", "3", "--quiet")
    b = gr.breathers(gr.from_types(types, xi=0.5), near=edge, max_points=3)
    assert len(b) == 3
    for key, column in (("freq_khz", "freq_khz"), ("energy", "energy_J"), ("max_multiplier", "max_multiplier"),
                        ("residual", "residual")):
        assert_identical(getattr(b, key), csv[column])
    assert b.metadata["continuation"]["stop_reason"] == meta["continuation"]["stop_reason"]
    # The verdict and its completeness, as in the CSV (dense at 21 beads: every multiplier).
    assert (b.stable == (csv["stable"] == 1)).all() and (b.complete == (csv["complete"] == 1)).all()
    assert b.complete.all()
    assert (b.verdict_trusted == (csv["verdict_trusted"] == 1)).all() and b.verdict_trusted.all()
    assert b.verdict_untrusted_reason == "" and b.metadata["floquet"]["verdict_untrusted_reason"] is None
    assert b.profiles.shape == (3, 21) and b.open_fraction.shape == (3, 22) and b.multipliers.shape == (3, 42)
    # Symplectic: the product of the multipliers is 1.
    assert np.allclose(np.prod(b.multipliers, axis=1), 1, atol=1e-8)
    assert (b.freq_khz < b.seed_khz).all()


def test_breathers_rejects_bad_input():
    with pytest.raises(ValueError, match="mode"):
        gr.breathers(gr.diatomic(N=21))
    with pytest.raises(TypeError):
        gr.breathers("not a chain", mode=3)
    # Two seeds, or an offset from the seed with the start given: one would be ignored, so both are refused.
    with pytest.raises(ValueError, match=r"^near: give either a seed mode number \(mode\) or a frequency"):
        gr.breathers(gr.diatomic(N=21, xi=0.5), mode=3, near=30.0, max_points=1)
    with pytest.raises(ValueError, match=r"^start_offset: takes effect only without start_khz"):
        gr.breathers(gr.diatomic(N=21, xi=0.5), mode=3, start_khz=30.0, start_offset=1e-2, max_points=1)


@pytest.mark.parametrize("name", ["tolerance", "stability_tolerance"])
@pytest.mark.parametrize("bad", [0.0, -1e-10, float("nan"), float("inf")])
def test_breathers_refuses_tolerances_that_are_not_positive(name, bad):
    # Refused by the library, as the tool's --tolerance and --stability-tolerance are (once zero or
    # below ran Newton to its limit, or called every orbit unstable).
    with pytest.raises(ValueError, match=name):
        gr.breathers(gr.diatomic(N=21, xi=0.5), mode=3, max_points=1, **{name: bad})


def test_breathers_from_a_profile_and_by_arclength():
    types = [2 if i % 2 == 0 else 1 for i in range(21)]
    chain = gr.from_types(types, xi=0.5)
    edge = gr.band_edges(xi=0.5).fb2
    natural = gr.breathers(chain, near=edge, max_points=4)
    # Pseudo-arclength takes over from the third point: the same branch, on other frequencies.
    arc = gr.breathers(chain, near=edge, max_points=4, continuation="arclength")
    assert arc.metadata["continuation"]["method"].startswith("pseudo-arclength")
    assert_identical(arc.freq_khz[:2], natural.freq_khz[:2])
    assert (np.diff(arc.freq_khz) < 0).all() and (arc.residual <= 1e-10).all()
    # Seeded from the natural branch's last profile at its frequency: Newton lands on that point.
    again = gr.breathers(chain, seed_profile=natural.profiles[-1], start_khz=natural.freq_khz[-1], max_points=1)
    assert again.seed_mode == 0
    assert np.allclose(again.profiles[0], natural.profiles[-1], rtol=0, atol=1e-6 * np.abs(natural.profiles[-1]).max())
    with pytest.raises(ValueError, match="continuation"):
        gr.breathers(chain, near=edge, continuation="pseudo")
    with pytest.raises(ValueError, match="seed_profile"):
        gr.breathers(chain, seed_profile=natural.profiles[-1][:-1], start_khz=natural.freq_khz[-1])


def test_breathers_by_newton_krylov():
    types = [2 if i % 2 == 0 else 1 for i in range(21)]
    chain = gr.from_types(types, xi=0.5)
    edge = gr.band_edges(xi=0.5).fb2
    dense = gr.breathers(chain, near=edge, max_points=2)
    krylov = gr.breathers(chain, near=edge, max_points=2, newton="krylov", floquet="dense")
    assert dense.metadata["shooting"]["newton"] == "dense" and dense.metadata["floquet"]["method"] == "dense"
    assert krylov.metadata["shooting"]["newton"] == "krylov"
    assert all(len(p["krylov_iterations"]) > 0 for p in krylov.metadata["points"])
    assert np.allclose(krylov.freq_khz, dense.freq_khz, rtol=1e-12, atol=0)
    assert (krylov.residual <= 1e-10).all()
    assert np.allclose(krylov.max_multiplier, dense.max_multiplier, rtol=0, atol=1e-8)
    with pytest.raises(ValueError, match="floquet"):
        gr.breathers(chain, near=edge, floquet="lapack")
    with pytest.raises(ValueError, match="newton"):
        gr.breathers(chain, near=edge, newton="gmres")
    with pytest.raises(ValueError, match="multipliers"):
        gr.breathers(chain, near=edge, floquet="arpack", multipliers=40)


def test_breathers_at_zero_precompression_on_onsite_springs():
    # A Newton's cradle on springs: beads touching at F0 = 0, each on a spring of 1e7 N/m (8.36 kHz).
    chain = gr.quasiperiodic("s1", N=21, modulation=0.0, phase=0.0, F0=0.0, k0_n_per_m=1e7)
    b = gr.breathers(chain, max_points=3, start_offset=1e-2)
    assert b.seed_site == 11 and b.seed_mode == 0
    assert b.metadata["seed"]["site"] == 11
    assert (np.diff(np.concatenate(([b.seed_khz], b.freq_khz))) > 0).all()  # above the on-site frequency, going up
    assert (b.residual <= 1e-10).all() and (b.centre == 11).all()
    assert np.allclose(np.prod(b.multipliers, axis=1), 1, atol=1e-8)
    # The Floquet verdicts at F0 = 0 are the discretized map's, not the orbit's (issue 42, item 5).
    assert b.verdict_trusted.dtype == bool and not b.verdict_trusted.any()
    assert "F0 = 0" in b.verdict_untrusted_reason
    assert b.metadata["floquet"]["verdict_untrusted_reason"] == b.verdict_untrusted_reason
    with pytest.raises(ValueError, match="F0"):  # no springs: no breathers at F0 = 0
        gr.breathers(gr.quasiperiodic("s2", N=21, F0=0.0), site=11)
    with pytest.raises(ValueError, match="mode"):
        gr.breathers(chain, mode=3)


def test_the_branch_keywords_are_the_library_table_and_near_khz_is_near():
    """granular.breathers' keywords are breather_parameters()' rows with their C++ defaults (a frequency that may be
    none: None); near_khz, the former keyword of near, still works with a FutureWarning."""
    taken = inspect.signature(gr.breathers).parameters
    config = gr._core.BreatherBranchConfig()
    for name, word, _ in gr._core.BreatherBranchConfig._parameters:
        assert word in taken, word
        default = getattr(config, name)
        assert taken[word].default == (None if isinstance(default, float) and math.isnan(default) else default), word
    assert taken["near"].default is None and "near_khz" not in taken
    chain = gr.from_types([1, 1, 2, 1, 1, 2, 1, 1, 2, 1, 1, 2, 1, 1, 2, 1, 1, 2, 1, 1, 2], xi=0.5)
    now = gr.breathers(chain, near=42, max_points=1)
    with pytest.warns(FutureWarning, match="'near_khz' is deprecated: use 'near'"):
        before = gr.breathers(chain, near_khz=42, max_points=1)
    assert list(now.freq_khz) == list(before.freq_khz)
