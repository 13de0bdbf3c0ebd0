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


def test_seconds_typed_as_milliseconds_is_named_before_the_run():
    # As an error, the warning stops the call before it integrates 10 s of the paper's chain.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(RuntimeWarning, match=r"^T 10: waves from the kick reach a wall after about"):
            gr.spreading(gr.anderson(N=2501), T=10)
