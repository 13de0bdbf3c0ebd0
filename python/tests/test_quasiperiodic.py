"""granular.quasiperiodic: the same chain as the tools' --quasi (spectrum compared exactly with the
spectrum tool's CSV), the modulation formula of docs/physics.md, "Quasiperiodic chains", and bad
keywords named in the ValueError."""
import inspect
import math
import re

import numpy as np
import pytest

import granular as gr
from conftest import assert_identical


@pytest.mark.parametrize("kind", ["s1", "s2", "cylinders"])
def test_quasiperiodic_spectrum_equals_the_spectrum_tool(tools, kind):
    args = ["--quasi", kind, "--modulation", "0.4", "--ratio", "2/5", "--N", "60", "--seed", "4", "--realization", "3"]
    csv, meta = tools.run("spectrum", *args)
    chain = gr.quasiperiodic(kind, N=60, modulation=0.4, ratio="2/5", seed=4, realization=3)
    result = gr.spectrum(chain)
    assert_identical(result.freq_khz, csv["freq_khz"])
    assert_identical(result.ipr, csv["ipr"])
    assert result.metadata["chain"] == meta["chain"]
    assert meta["chain"]["quasiperiodic"]["kind"] == kind


def test_s2_masses_follow_the_cosine():
    chain = gr.quasiperiodic("s2", N=30, modulation=0.5, ratio=0.3, phase=1.2)
    n = np.arange(1, 31)
    m = 8027.17 * 4 / 3 * math.pi * gr.paper_r1**3
    np.testing.assert_allclose(chain.mass, m * (1 + 0.5 * np.cos(2 * math.pi * 0.3 * n + 1.2)), rtol=1e-14)
    assert len(chain.onsite) == 0
    assert len(gr.quasiperiodic("s1", N=30, modulation=0.5).onsite) == 30


@pytest.mark.parametrize(
    "keywords, name",
    [({"modulation": 1.0}, "modulation"), ({"ratio": 0}, "ratio"), ({"ratio": "abc"}, "ratio"),
     ({"kind": "s3"}, "^kind"), ({"kind": "cylinders", "angle": 200}, "angle"),
     # Axes so near parallel that the contact ellipse is a line, not a Hertz point contact.
     ({"kind": "cylinders", "modulation": 0.99}, "^modulation 0.99: at 0.45 degrees"),
     ({"kind": "cylinders", "angle": 0.5}, "^angle 0.5: at 0.5 degrees")])
def test_bad_keywords_are_named(keywords, name):
    with pytest.raises(ValueError, match=name):
        gr.quasiperiodic(**keywords)


def test_cylinders_near_parallel_are_warned():
    # The contact ellipse above 0.1 R at the angle nearest parallel (4.5 degrees): a RuntimeWarning naming the keyword.
    with pytest.warns(RuntimeWarning, match=r"^modulation 0.9: at 4.5 degrees the cylinders' contact ellipse"):
        gr.quasiperiodic("cylinders", N=20, modulation=0.9)


def test_kind_names_are_case_insensitive():
    for typed, kind in (("S1", "s1"), ("S2", "s2"), ("Cylinders", "cylinders")):
        chain = gr.quasiperiodic(typed, N=30, modulation=0.5, phase=0.4)
        assert_identical(gr.spectrum(chain).freq_khz, gr.spectrum(gr.quasiperiodic(kind, N=30, modulation=0.5,
                                                                                    phase=0.4)).freq_khz)
        assert chain.metadata["quasiperiodic"]["kind"] == kind
    assert gr.localization(quasi="S1", modulation=0.3, N=100, f=1).N == 100


CHAIN = gr.anderson(N=31)
SHORT = dict(N=31, realizations=1, T=1e-4, fit=(5e-5, 1e-4))


@pytest.mark.parametrize("call, keywords, message", [
    (gr.quasiperiodic, dict(kind="s1", angle=30), r"^angle: takes effect only with kind cylinders, not kind s1$"),
    (gr.quasiperiodic, dict(kind="s2", k0=8), r"^k0: takes effect only with kind s1, not kind s2$"),
    (gr.quasiperiodic, dict(kind="c", k0_n_per_m=1e6), r"^k0_n_per_m: takes effect only with kind s1, not kind c$"),
    (gr.butterfly, dict(kind="s2", angle=30, ratios="0.2"), r"^angle: takes effect only with kind cylinders"),
    (gr.localization, dict(N=100, f=1, modulation=0.5), r"^modulation: takes effect only with quasi, which is not"),
    (gr.localization, dict(N=100, f=1, phase=0.4), r"^phase: takes effect only with quasi, which is not given$"),
    (gr.ipr_map, dict(N=40, quasi="s2", angle=30), r"^angle: takes effect only with quasi cylinders, not quasi s2$"),
    (gr.ipr_map, dict(N=40, ratio="2/7"), r"^ratio: takes effect only with quasi, which is not given$"),
    (gr.transport, dict(SHORT, k0=8), r"^k0: takes effect only with quasi s1, which is not given$"),
    (gr.exponent_table, dict(chains="none", quasi="s2", k0=8, **SHORT), r"^k0: takes effect only with quasi s1"),
    (gr.spreading, dict(chain=CHAIN, map_stride=2), r"^map_stride: takes effect only with energy_map, which is off$"),
    (gr.spreading, dict(chain=CHAIN, spectrum_of="velocity"), r"^spectrum_of: takes effect only with spectral_density"),
    (gr.spreading, dict(chain=CHAIN, force_samples=50), r"^force_samples: takes effect only with forces_at"),
    (gr.spreading, dict(chain=CHAIN, energy_guard="warn", max_energy_error=0), r"^energy_guard: takes effect only"),
    (gr.spreading, dict(chain=CHAIN, active_window=False, window_threshold=1e-20), r"^window_threshold: takes effect"),
    (gr.spreading, dict(chain=CHAIN, reference_max_step=2e-8), r"^reference_max_step: takes effect only with "
                                                                r"integrator reference, not integrator saba2c$"),
    (gr.spreading, dict(chain=CHAIN, renormalize=5), r"^renormalize: takes effect only with mle, which is off$"),
])
def test_a_keyword_that_would_take_no_effect_is_refused(call, keywords, message):
    """As the tools refuse such an option (tests/tools/dependent_options_test.cpp): never silently ignored."""
    with pytest.raises(ValueError, match=message):
        call(**keywords)


def test_butterfly_equals_the_tool_and_draws(tools):
    csv, meta = tools.run("butterfly", "--quasi", "s1", "--modulation", "0.3", "--ratios", "0.1,0.3,0.618", "--N",
                          "50", "--quiet", output="b")
    result = gr.butterfly("s1", modulation=0.3, ratios=[0.1, 0.3, 0.618], N=50)
    assert_identical(result.freq_khz, csv["freq_khz"])
    assert_identical(result.ipr, csv["ipr"])
    assert_identical(result.dimension, np.asarray(meta["box_counting"]["dimension"]))
    assert result.metadata["chain"] == meta["chain"]
    # each column is the spectrum of that ratio's chain
    one = gr.spectrum(gr.quasiperiodic("s1", N=50, modulation=0.3, ratio=0.3), method="fast")
    assert_identical(result.freq_khz[result.ratio == 0.3], one.freq_khz)
    import granular.plot as gp
    fig = gp.butterfly(result)
    assert len(fig.axes) >= 2
    fig = gp.butterfly(tools.path("b.csv"))
    assert len(fig.axes) >= 2


def test_quasi_keywords_run_the_tools_chains(tools):
    # localization: the transfer matrices with the on-site springs, equal to the tool's numbers
    csv, _ = tools.run("localization", "--quasi", "s1", "--modulation", "0.7", "--phase", "0.4", "--N", "20000",
                       "--f", "20:30:5")
    result = gr.localization(quasi="s1", modulation=0.7, phase=0.4, N=20000, f="20:30:5")
    assert_identical(result.lyapunov, csv["lyapunov"])
    # and the same as a granular.Chain of the same recipe
    chain = gr.quasiperiodic("s1", N=20000, modulation=0.7, phase=0.4)
    assert_identical(gr.localization(chain, f="20:30:5").lyapunov, result.lyapunov)
    # ipr-map: one cell over phases, the tool's numbers
    csv, _ = tools.run("ipr-map", "--quasi", "s2", "--modulation", "0.5", "--N", "40", "--realizations", "3")
    m = gr.ipr_map(quasi="s2", modulation=0.5, N=40, realizations=3)
    assert_identical(m.ipr.ravel(), csv["ipr"])
    # transport over a phase ensemble of S1, the spreading tool's ensemble
    csv, _ = tools.run("spreading", "--quasi", "s1", "--modulation", "0.7", "--N", "101", "--T", "2e-4",
                       "--fit", "1e-4:2e-4", "--t-star", "1e-4", "--realizations", "2", "--samples", "10")
    t = gr.transport(quasi="s1", modulation=0.7, N=101, T=2e-4, fit=(1e-4, 2e-4), t_star=1e-4, realizations=2,
                     samples=10)
    assert_identical(t.m2, csv["m2"])
    assert np.all(t.energy_error < 1e-5)  # SABA2C at 1 us, omega tau <= 0.17 on S1: measured <= 2.5e-6


def test_exponent_table_over_phases_equals_the_exponents_tool(tools):
    flags = ["--chains", "none", "--quasi", "s1", "--modulation", "0.5", "--F0", "10", "--ic", "displacement",
             "--N", "151", "--T", "1e-3", "--fit", "4e-4:1e-3", "--t-star", "4e-4", "--realizations", "3",
             "--samples", "20", "--profile-F0", "none", "--bootstrap", "50", "--quiet"]
    csv, meta = tools.run("exponents", *flags, output="qexp")
    table = gr.exponent_table(chains="none", quasi="s1", modulation=0.5, F0=[10], ic=["displacement"], N=151,
                              T=1e-3, fit=(4e-4, 1e-3), t_star=4e-4, realizations=3, samples=20, profile_F0=None,
                              bootstrap=50)
    assert list(table.table["disorder"]) == ["quasi-s1"]
    for key in ("gamma", "gamma_err", "eta", "max_energy_error"):
        assert_identical(table.table[key], csv[key])
    assert table.metadata["cases"] == meta["cases"]
    with pytest.raises(ValueError, match="chains"):
        gr.exponent_table(chains="none", F0=[10], N=151, T=1e-3, realizations=1)


def test_quasi_keyword_errors_name_the_keyword():
    with pytest.raises(ValueError, match="modulation"):
        gr.localization(quasi="s1", modulation=1.2, N=100, f="1:2")
    with pytest.raises(ValueError, match="N 200000000: more than 1e8"):  # stored, not drawn in pieces
        gr.localization(quasi="s1", modulation=0.3, N=2e8, f="1:2")
    with pytest.raises(ValueError, match="quasi"):
        gr.ipr_map(quasi="s4", N=40)


def test_dynamical_butterfly_equals_the_tool_and_draws(tools):
    csv, meta = tools.run("butterfly", "--from", "dynamics", "--quasi", "cylinders", "--modulation", "0.3",
                          "--ratios", "0.3,0.5", "--N", "10", "--phase", "0.4", "--T", "2e-3",
                          "--spectrum-samples", "401", "--quiet", output="d")
    result = gr.dynamical_butterfly("cylinders", modulation=0.3, ratios=[0.3, 0.5], N=10, phase=0.4, T=2e-3,
                                    spectrum_samples=401)
    rows = result.rows()
    for key in ("ratio", "freq_khz", "power"):
        assert_identical(rows[key], csv[key])
    assert result.power.shape == (2, 201)
    assert result.metadata["chain"] == meta["chain"]
    assert result.metadata["spectrum"] == meta["spectrum"]
    # thread-count invariant
    one = gr.dynamical_butterfly("cylinders", modulation=0.3, ratios=[0.3, 0.5], N=10, phase=0.4, T=2e-3,
                                 spectrum_samples=401, threads=1)
    assert_identical(one.power, result.power)
    import granular.plot as gp
    eigen = gr.butterfly("cylinders", modulation=0.3, ratios=[0.3, 0.5], N=10, phase=0.4)
    assert len(gp.dynamical_butterfly(result, eigen).axes) >= 2
    assert len(gp.dynamical_butterfly(tools.path("d.csv")).axes) >= 2
    # the command line: python3 -m granular.plot dynamical-butterfly CSV --eigen CSV
    tools.run("butterfly", "--quasi", "cylinders", "--modulation", "0.3", "--ratios", "0.3,0.5", "--N", "10",
              "--phase", "0.4", "--quiet", output="e")
    from granular.plot.__main__ import main
    png = tools.path("d.png")
    assert main(["dynamical-butterfly", str(tools.path("d.csv")), "--eigen", str(tools.path("e.csv")), "--zoom",
                 "5:15", "-o", str(png)]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert main(["dynamical-butterfly", str(tools.path("e.csv"))]) == 2  # an eigen CSV: no power column


def test_dynamical_butterfly_peaks_are_the_eigenfrequencies():
    # S1 at a rational ratio: every local maximum of the power above 1e-6 lies within 1/T of an eigenfrequency of
    # the linear solver, and there is one per mode (beads of one mass: the bead sum has no cross terms between
    # modes, so between two modes the power only falls)
    T = 2e-2
    result = gr.dynamical_butterfly("s1", modulation=0.4, ratios=[1 / 3], N=10, phase=0.4, T=T, spectrum_samples=4001)
    modes = gr.spectrum(gr.quasiperiodic("s1", N=10, modulation=0.4, ratio=1 / 3, phase=0.4)).freq_khz
    g, f = result.power[0], result.freq_khz
    peak = (g[1:-1] > g[:-2]) & (g[1:-1] > g[2:]) & (g[1:-1] > 1e-6)
    peaks = f[1:-1][peak]
    assert len(peaks) == len(modes)
    resolution = 1 / T / 1e3
    assert np.max(np.min(np.abs(peaks[:, None] - modes[None, :]), axis=1)) <= resolution
    assert np.max(np.min(np.abs(modes[:, None] - peaks[None, :]), axis=1)) <= resolution


def test_every_parameter_of_the_dynamical_butterfly_table_is_a_documented_keyword():
    """The library describes the run's numbers once (dynamical_butterfly_parameters); the butterfly tool makes its
    --from dynamics flags of it. A parameter added there must reach granular.dynamical_butterfly too: as a keyword
    with the library's default, documented in the docstring."""
    taken = inspect.signature(gr.dynamical_butterfly).parameters
    defaults = gr._core.DynamicalButterflyConfig()
    assert len(defaults._parameters) >= 4
    for name, word, _ in defaults._parameters:
        assert word in taken, f"dynamical_butterfly takes no keyword {word}"
        assert taken[word].default == getattr(defaults, name), f"{word}: not the library's default"
        assert re.search(rf"(?<![\w-]){word}(?![\w-])", gr.dynamical_butterfly.__doc__), \
            f"dynamical_butterfly's docstring does not explain {word}"


@pytest.mark.parametrize(
    "keywords, name",
    [({"amplitude": 0}, "amplitude"), ({"amplitude": 1.0}, "amplitude"),
     ({"spectrum_samples": 50}, "spectrum_samples"), ({"spectrum_samples": 101}, "spectrum_samples"), ({"dt": 1e-4}, "dt"), ({"T": -1}, "T"),
     ({"spectrum_of": "force"}, "spectrum_of"), ({"ratios": [0.5, 0]}, "ratios"), ({"integrator": "rk4"}, "integrator"),
     ({"force_law": "spring"}, "force_law"), ({"modulation": 1.5}, "modulation")])
def test_dynamical_butterfly_bad_keywords_are_named(keywords, name):
    with pytest.raises(ValueError, match=name):
        gr.dynamical_butterfly("cylinders", **{"N": 10, "ratios": [0.5], **keywords})
