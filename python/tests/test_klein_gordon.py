"""granular.klein_gordon: its keywords are the library's klein_gordon_parameters() rows with KleinGordonCase's C++
defaults, it returns what the klein-gordon tool writes, and granular.plot draws it from either."""
import inspect
import os
import subprocess
import sys

import numpy as np
import pytest

import granular as gr
from granular import _core

from conftest import assert_identical


def test_signature_is_the_table_with_its_cpp_defaults():
    rows = _core.KleinGordonCase._parameters
    defaults = _core.KleinGordonCase()
    signature = inspect.signature(gr.klein_gordon).parameters
    assert [keyword for _, keyword, _ in rows] == list(signature)
    assert {"N", "W", "seed", "energy", "block", "dt", "T", "samples", "mle", "realizations", "threads",
            "fit", "energy_map"} == set(signature)
    for name, keyword, help_text in rows:
        assert signature[keyword].default == (getattr(defaults, name) or None if name == "fit" else
                                              getattr(defaults, name)), keyword
        assert signature[keyword].kind == inspect.Parameter.KEYWORD_ONLY
        assert help_text.split(" (")[0][:30] in gr.klein_gordon.__doc__, keyword
    assert signature["dt"].default == 0.2 and signature["W"].default == 4.0


def test_the_tool_writes_the_same_run(tools):
    args = dict(N=96, W=3.0, seed=2, energy=0.4, T=300.0, samples=20)
    csv, meta = tools.run("klein-gordon", *[f"--{k}={v}" for k, v in args.items()], "--quiet")
    r = gr.klein_gordon(**args)
    for column, key in (("t", "t"), ("m2", "m2"), ("P", "P"), ("mle", "mle"), ("mean_log10_mle", "mean_log10_mle")):
        assert_identical(csv[column], r[key])
    assert meta["parameters"] == r.metadata["parameters"]
    assert meta["max_energy_error"] == r.max_energy_error < 1e-4
    assert r.runs_m2.shape == (1, len(r.t))
    assert_identical(r.runs_m2[0], r.m2)


def test_an_ensemble_is_its_realizations_means_on_any_thread_count(tools):
    args = dict(N=64, block=21, energy=0.1, seed=7, T=200.0, samples=10, realizations=3)
    one = gr.klein_gordon(threads=1, **args)
    two = gr.klein_gordon(threads=2, **args)
    for key in ("t", "m2", "P", "mle", "mean_log10_mle", "runs_m2", "runs_mle"):
        assert_identical(one[key], two[key])
    assert one.runs_P.shape == (3, len(one.t))
    # the means in index order, as the library sums them
    expected = one.runs_m2[0] / 3 + one.runs_m2[1] / 3 + one.runs_m2[2] / 3
    np.testing.assert_allclose(one.m2, expected, rtol=1e-15)
    csv, _ = tools.run("klein-gordon", "--N", 64, "--block", 21, "--energy", 0.1, "--seed", 7, "--T", 200,
                       "--samples", 10, "--realizations", 3, "--threads", 2, "--quiet")
    assert_identical(csv["m2"], one.m2)
    assert_identical(csv["mean_log10_mle"], one.mean_log10_mle)


def test_exponents_are_the_tools_and_the_slopes_of_the_curves(tools):
    args = dict(N=64, block=21, energy=0.1, seed=7, T=400.0, samples=30, realizations=3)
    r = gr.klein_gordon(fit=(10, 400), threads=2, **args)
    _, meta = tools.run("klein-gordon", *[f"--{k}={v}" for k, v in args.items()], "--fit", "10:400", "--quiet")
    assert r.exponents == meta["exponents"] == r.metadata["exponents"]
    assert r.metadata["parameters"]["fit"] == [10.0, 400.0]
    inside = (r.t >= 10) & (r.t <= 400)
    assert r.exponents["samples"] == inside.sum() >= 3
    # the same least squares as numpy's, to rounding
    log_t = np.log10(r.t[inside])
    for key, curve in (("alpha", np.log10(r.m2)), ("alpha_P", np.log10(r.P)), ("alpha_Lambda", r.mean_log10_mle)):
        assert r.exponents[key] == pytest.approx(np.polyfit(log_t, curve[inside], 1)[0], abs=1e-10), key
    slopes = [np.polyfit(log_t, np.log10(m2[inside]), 1)[0] for m2 in r.runs_m2]
    assert r.exponents["alpha_mean"] == pytest.approx(np.mean(slopes), abs=1e-10)
    assert r.exponents["alpha_error"] == pytest.approx(np.std(slopes, ddof=1) / np.sqrt(3), abs=1e-10)
    assert gr.klein_gordon(N=32, T=20.0, samples=4).exponents is None
    assert gr.klein_gordon(N=32, T=20.0, samples=8, fit=None).exponents is None
    one = gr.klein_gordon(N=32, T=20.0, samples=8, fit=[1, 20])
    assert set(one.exponents) == {"fit", "samples", "alpha", "alpha_P", "alpha_Lambda", "definition"}


@pytest.mark.parametrize("fit", [(0, 10), (10, 5), (10, 2e4), (100, 110), (1, 2, 3), (5,), "a:b"])
def test_a_bad_fit_window_is_a_value_error_naming_it(fit):
    with pytest.raises(ValueError, match="fit"):
        gr.klein_gordon(N=32, fit=fit)


def test_energy_map_rows_sum_to_the_energy_and_equal_the_tools_file(tools):
    import h5py

    args = dict(N=64, energy=0.4, seed=3, T=300.0, samples=20, realizations=2)
    r = gr.klein_gordon(energy_map=True, threads=2, **args)
    assert r.energy_map.shape == (len(r.t), 64)
    # a single site of energy E: H = E, and each row sums to it within the scheme's energy error
    sums = r.energy_map.sum(axis=1)
    assert np.all(np.abs(sums - 0.4) / 0.4 <= r.max_energy_error + 1e-13)
    assert r.energy_map[0].argmax() == 31  # the excited centre site (from 0)
    tools.run("klein-gordon", *[f"--{k}={v}" for k, v in args.items()], "--energy-map", "--quiet", output="kg")
    with h5py.File(tools.path("kg-energy.h5"), "r") as f:
        assert_identical(f["energy"][...], r.energy_map)
        assert_identical(f["t"][...], r.t)
        assert list(f["site"][...]) == list(range(1, 65))
    assert gr.klein_gordon(N=32, T=20.0, samples=4).energy_map is None
    with pytest.raises(ValueError, match="energy_map"):
        gr.klein_gordon(N=10**7, samples=100, energy_map=True)


def test_without_mle_there_is_no_lambda():
    r = gr.klein_gordon(N=32, T=20.0, samples=4, mle=False)
    assert r.mle is None and r.mean_log10_mle is None and r.runs_mle is None
    assert len(r.m2) == 4


@pytest.mark.parametrize("keywords, name", [
    ({"N": 1}, "N"), ({"W": 0.0}, "W"), ({"energy": -1.0}, "energy"), ({"N": 10, "block": 11}, "block"),
    ({"dt": 0.0}, "dt"), ({"T": 0.01}, "T"), ({"samples": 0}, "samples"), ({"realizations": 0}, "realizations"),
    ({"threads": -1}, "threads"), ({"N": 2.5}, "N"),
])
def test_bad_keywords_are_value_errors_naming_them(keywords, name):
    with pytest.raises(ValueError, match=name):
        gr.klein_gordon(**keywords)


def test_an_unknown_keyword_is_a_type_error():
    with pytest.raises(TypeError, match="tau"):
        gr.klein_gordon(tau=0.1)


def test_figure_from_a_result_and_from_the_tools_csv(tools):
    r = gr.klein_gordon(N=64, T=100.0, samples=15, realizations=2, threads=1)
    fig = gr.plot.klein_gordon(r)
    assert len(fig.axes) == 3
    assert all(ax.get_xscale() == "log" and ax.get_yscale() == "log" for ax in fig.axes)
    assert "langle" in fig.axes[2].get_ylabel()  # 10^<log10 Lambda> of an ensemble
    tools.run("klein-gordon", "--N", 64, "--T", 100, "--samples", 15, "--mle=false", "--quiet", output="kg.csv")
    assert len(gr.plot.klein_gordon(tools.path("kg.csv")).axes) == 2  # no Lambda: m2 and P
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(os.path.abspath(gr.__file__))))
    done = subprocess.run([sys.executable, "-m", "granular.plot", "klein-gordon", "kg.csv"], capture_output=True,
                          text=True, cwd=tools.folder, env=env)
    assert done.returncode == 0, done.stderr
    assert (tools.folder / "kg.png").stat().st_size > 0
