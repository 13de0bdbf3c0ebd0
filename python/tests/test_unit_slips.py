"""Unit slips (millimetres typed as metres, Hz as kHz, milliseconds as seconds) draw a
RuntimeWarning naming the keyword, as the tools print one naming the option; the same values
typed correctly draw none."""
import warnings

import pytest

import granular as gr


def no_warning(call, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return call(*args, **kwargs)


def test_a_radius_in_metres_is_named():
    with pytest.warns(RuntimeWarning, match=r"^R1: radius 4\.76 m"):
        gr.anderson(N=20, R1=4.76)
    no_warning(gr.anderson, N=20, R1=4.76e-3)
    with pytest.warns(RuntimeWarning, match=r"^radii\[1\]: radius 4\.76 m .*\(and 1 more\)"):
        gr.from_radii([4.76e-3, 4.76, 3.0])
    with pytest.warns(RuntimeWarning, match=r"^R1: radius 4\.76 m"):
        gr.localization(N=1000, f=10, R1=4.76)


def test_hertz_typed_as_kilohertz_is_named():
    chain = gr.anderson(N=100)
    with pytest.warns(RuntimeWarning, match=r"^near 15000: above every frequency of this chain"):
        gr.spectrum(chain, near=15000, count=3)
    no_warning(gr.spectrum, chain, near=15, count=3)
    with pytest.warns(RuntimeWarning, match=r"^f 15000: above every frequency of this chain"):
        gr.localization(N=1000, f=15000)
    no_warning(gr.localization, N=1000, f=15)


@pytest.mark.parametrize("call, keywords, named", [
    (gr.breathers, dict(near=33810), "near 33810"),
    (gr.breathers, dict(start_khz=20000), "start_khz 20000"),
    (gr.breathers, dict(mode=30, target_khz=20000), "target_khz 20000"),
    (gr.spreading, dict(ic="mode", near=15000, energy=1e-9), "near 15000"),
    (gr.exponent_table, dict(chains="none", quasi="s2", N=51, T=1e-4, fit=(2e-5, 1e-4), t_star=2e-5, realizations=1,
                             ic=["mode"], near=15000, energy=1e-9, F0=[10], profile_F0=[]), "near 15000"),
    (gr.ipr_map, dict(near=15000, count=3), "near 15000"),
    (gr.ipr_map, dict(window=(15000, 16000)), "window 15000"),
])
def test_every_frequency_keyword_is_checked_for_hertz_typed_as_kilohertz(call, keywords, named):
    # As an error, the warning stops the call before its run (a breather branch seeded from the top mode).
    args = () if call in (gr.ipr_map, gr.exponent_table) else (gr.anderson(N=30),)
    if call is gr.ipr_map:
        keywords = dict(keywords, N=30, xi=0.5, q=0.5, realizations=2)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(RuntimeWarning, match=rf"^{named}: above every frequency of this chain"):
            call(*args, **keywords)


def test_seconds_typed_as_milliseconds_is_named_before_the_run():
    # As an error, the warning stops the call before it integrates 10 s of the paper's chain.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(RuntimeWarning, match=r"^T 10: waves from the kick reach a wall after about"):
            gr.spreading(gr.anderson(N=2501), T=10)
