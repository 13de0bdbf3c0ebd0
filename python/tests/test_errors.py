"""Bad input never crashes: ValueError naming the keyword (as the tools' options are named),
OSError for files, granular.NumericalError for a failed guard or solver, TypeError for a value
of the wrong Python type — including NaN, infinities, negative sizes, wrong shapes and dtypes."""
import math
import re

import numpy as np
import pytest

import granular as gr

NAN, INF = math.nan, math.inf
CHAIN = gr.anderson(N=30)


def raises_naming(keyword, call, *args, **kwargs):
    """`call` raises ValueError whose message starts with the keyword (the library's message format)."""
    with pytest.raises(ValueError) as info:
        call(*args, **kwargs)
    message = str(info.value)
    assert re.match(rf"{re.escape(keyword)}\b", message), f"expected a message naming {keyword!r}, got {message!r}"
    assert "--" not in message, f"a command-line flag in a Python message: {message!r}"
    return message


@pytest.mark.parametrize("kwargs,keyword", [
    (dict(N=1), "N"), (dict(N=-5), "N"), (dict(N=10**9), "N"),
    (dict(q=1.5), "q"), (dict(q=NAN), "q"), (dict(q=-INF), "q"),
    (dict(xi=0.0), "xi"), (dict(xi=NAN), "xi"), (dict(xi=2.0), "xi"),
    (dict(F0=-1.0), "F0"), (dict(F0=INF), "F0"), (dict(F0=NAN), "F0"),
    (dict(R1=0.0), "R1"), (dict(R1=NAN), "R1"),
    (dict(seed=-1), "seed"), (dict(realization=-2), "realization"),
    (dict(material=gr.Material(young=-1.0)), "material"),
    (dict(material=gr.Material(poisson=NAN)), "material"),
])
def test_chain_keywords(kwargs, keyword):
    raises_naming(keyword, gr.anderson, **kwargs)


def test_chain_inputs_of_the_wrong_kind():
    raises_naming("disorder", gr.random_chain, "B")
    raises_naming("types", gr.from_types, [1, 3, 2])
    raises_naming("types", gr.from_types, [1.5, 2])
    raises_naming("types", gr.from_types, [1])
    raises_naming("types", gr.from_types, [[1, 2], [2, 1]])
    raises_naming("types", gr.from_types, "1212")
    raises_naming("types", gr.from_types, ["a", "b"])
    raises_naming("radii", gr.from_radii, [1e-3, NAN])
    raises_naming("radii", gr.from_radii, [1e-3, -1e-3])
    raises_naming("radii", gr.from_radii, np.ones((3, 2)) * 1e-3)
    raises_naming("radii", gr.from_radii, [1e-3])
    raises_naming("radii", gr.from_radii, np.array([], dtype=np.float32))
    raises_naming("radii", gr.from_radii, {"a": 1})
    raises_naming("F0", gr.from_radii, [1e-3, 1e-3], F0=-2.0)
    with pytest.raises(TypeError):
        gr.anderson(N="100")
    with pytest.raises(TypeError):
        gr.anderson(N=10.5)
    with pytest.raises(TypeError):
        gr.spectrum("a chain")


def test_spectrum_keywords():
    raises_naming("near", gr.spectrum, CHAIN, near=5.0)
    raises_naming("count", gr.spectrum, CHAIN, count=5)
    raises_naming("near", gr.spectrum, CHAIN, near=NAN, count=3, method="bisect")
    raises_naming("near", gr.spectrum, CHAIN, near=-1.0, count=3, method="bisect")
    raises_naming("count", gr.spectrum, CHAIN, near=5.0, count=0, method="bisect")
    raises_naming("count", gr.spectrum, CHAIN, near=5.0, count=31, method="bisect")
    raises_naming("count", gr.spectrum, CHAIN, near=5.0, count=-(2**62), method="bisect")
    raises_naming("window", gr.spectrum, CHAIN, window=(5.0,), method="bisect")
    raises_naming("window", gr.spectrum, CHAIN, window=(9.0, 3.0), method="bisect")
    raises_naming("window", gr.spectrum, CHAIN, window=(0.0, INF), method="bisect")
    raises_naming("window", gr.spectrum, CHAIN, window=(1.0, 2.0), near=1.0, count=1)
    raises_naming("method", gr.spectrum, CHAIN, method="qr")
    raises_naming("method", gr.spectrum, CHAIN, near=5.0, count=2, method="fast")
    raises_naming("method", gr.spectrum, CHAIN, method="bisect")
    raises_naming("vectors", gr.spectrum, CHAIN, method="fast", vectors=True)
    raises_naming("driver", gr.spectrum, CHAIN, driver="dsyev")
    raises_naming("lanes", gr.spectrum, CHAIN, near=5.0, count=2, method="bisect", lanes=0)
    raises_naming("tolerance", gr.spectrum, CHAIN, near=5.0, count=2, method="arpack", tolerance=NAN)
    # a setting of a solver that does not run is refused, not ignored
    assert "not with every mode" in raises_naming("lanes", gr.spectrum, CHAIN, lanes=4)
    assert "method arpack or slepc, not method lapack" in raises_naming(
        "tolerance", gr.spectrum, CHAIN, near=5.0, count=2, tolerance=1e-8)
    raises_naming("subspace", gr.spectrum, CHAIN, near=5.0, count=2, method="bisect", subspace=30)
    gr.spectrum(CHAIN, near=5.0, count=2, method="bisect", lanes=4)  # where they act they are taken
    gr.spectrum(CHAIN, near=5.0, count=2, method="arpack", tolerance=1e-8, subspace=30)
    raises_naming("F0", gr.spectrum, gr.anderson(N=10, F0=0.0))  # the sonic vacuum has no linear spectrum
    raises_naming("F0", gr.dynamical_matrix, gr.anderson(N=10, F0=0.0))


def test_dynamical_matrix_of_arrays():
    raises_naming("off_diagonal", gr.DynamicalMatrix, [1.0, 2.0], [1.0, 2.0])
    raises_naming("diagonal", gr.DynamicalMatrix, [1.0, NAN], [0.5])
    raises_naming("diagonal", gr.DynamicalMatrix, [], [])
    raises_naming("off_diagonal", gr.DynamicalMatrix, [1.0, 2.0], [[0.5]])
    raises_naming("inverse_sqrt_mass", gr.DynamicalMatrix, [1.0, 2.0], [0.5], [1.0])
    raises_naming("inverse_sqrt_mass", gr.DynamicalMatrix, [1.0, 2.0], [0.5], [1.0, 0.0])
    raises_naming("diagonal", gr.DynamicalMatrix, np.array(["x", "y"]), [0.5])


def test_contact_law_and_band_edge_keywords():
    raises_naming("F0", gr.band_edges, F0=0.0)
    raises_naming("xi", gr.band_edges, xi=1.5)
    raises_naming("R1", gr.band_edges, R1=-1.0)
    raises_naming("contact", gr.fpu_coefficients, contact=-1.0, F0=1.0)
    raises_naming("F0", gr.fpu_coefficients, contact=1e9, F0=0.0)
    raises_naming("F0", gr.static_overlap, contact=1e9, F0=NAN)
    raises_naming("alpha", gr.nonlinearity_ratio, alpha=INF, contact=1e9, F0=1.0)
    raises_naming("radius_a", gr.hertz_coefficient, -1.0)
    raises_naming("max_distance", gr.cyclic_correlation, CHAIN, max_distance=30)
    raises_naming("types", gr.cyclic_correlation, gr.from_radii([1e-3, 2e-3]))
    raises_naming("distance", gr.correlation_theory, "A", 0.5, [1, 2.5])
    raises_naming("q", gr.correlation_theory, "A", NAN, 1)


def test_study_keywords():
    raises_naming("xi", gr.ipr_map, xi="0.1:")
    raises_naming("xi", gr.ipr_map, xi="0.5:0.1")
    raises_naming("xi", gr.ipr_map, xi=[0.5, NAN])
    raises_naming("xi", gr.ipr_map, xi=[])
    raises_naming("q", gr.ipr_map, q=[1.5])
    raises_naming("N", gr.ipr_map, N=1)
    raises_naming("F0", gr.ipr_map, F0=0.0)
    raises_naming("realizations", gr.ipr_map, realizations=0)
    raises_naming("threads", gr.ipr_map, threads=-1)
    raises_naming("solver", gr.ipr_map, solver="magic")
    raises_naming("solver", gr.ipr_map, solver="lapack-magic")
    raises_naming("method", gr.ipr_map, method="bisect")
    raises_naming("method", gr.ipr_map, near=15.0, count=2, method="fast")
    raises_naming("method", gr.ipr_map, near=15.0, count=2, method="slepc")
    raises_naming("near", gr.ipr_map, near=15.0)
    raises_naming("count", gr.ipr_map, count=3)
    raises_naming("disorder", gr.correlations, disorder="h")
    raises_naming("max_distance", gr.correlations, N=10, max_distance=10)
    raises_naming("realizations", gr.correlations, realizations=-3)
    raises_naming("f", gr.localization, N=100, f="-1:5")
    raises_naming("f", gr.localization, N=100, f=[5.0, 4.0])
    raises_naming("f", gr.localization, N=100, f=[1.0, NAN])
    raises_naming("segments", gr.localization, N=100, segments=1)
    raises_naming("N", gr.localization, N=2.5)
    raises_naming("N", gr.localization, N=1e13)
    raises_naming("F0", gr.localization, N=100, F0=0.0)
    raises_naming("F0", gr.localization, gr.anderson(N=10, F0=0.0))
    raises_naming("xi", gr.localization, N=100, xi=0.0)


def test_dynamics_keywords(tmp_path):
    c = gr.anderson(N=21)
    raises_naming("T", gr.spreading, c, T=0.0)
    raises_naming("T", gr.spreading, c, T=1.5e-6)
    raises_naming("T", gr.spreading, c, T=NAN)
    raises_naming("dt", gr.spreading, c, dt=-1e-6)
    raises_naming("samples", gr.spreading, c, samples=1)
    raises_naming("integrator", gr.spreading, c, integrator="euler")
    raises_naming("force_law", gr.spreading, c, force_law="spring")
    raises_naming("sampling", gr.spreading, c, sampling="random")
    raises_naming("site", gr.spreading, c, site=-1)
    raises_naming("site", gr.spreading, c, site=22)
    raises_naming("forces_at", gr.spreading, c, forces_at=[0])
    raises_naming("forces_at", gr.spreading, c, forces_at=[2.5])
    raises_naming("fit", gr.spreading, c, fit=(1e-3, 5e-4))
    raises_naming("fit", gr.spreading, c, fit=(1e-3,))
    raises_naming("ic", gr.spreading, c, ic="push")
    raises_naming("beta", gr.spreading, c, ic="velocity", beta="fast")
    raises_naming("beta", gr.spreading, c, ic="velocity", beta=0.0)
    raises_naming("alpha", gr.spreading, c, alpha=0.0)
    raises_naming("alpha", gr.spreading, c, alpha=1.0)  # past the beads' radii
    raises_naming("energy_guard", gr.spreading, c, energy_guard="ignore")
    raises_naming("centre", gr.spreading, c, centre="middle")
    raises_naming("spectrum_of", gr.spreading, c, spectral_density=True, spectrum_of="force")
    raises_naming("fit_step", gr.spreading, c, fit_step=1.5e-6)
    raises_naming("bootstrap", gr.transport, N=21, bootstrap=1)
    raises_naming("kappa", gr.spreading, c, kappa=0.0)
    raises_naming("force_law", gr.spreading, gr.anderson(N=21, F0=0.0), force_law="fpu")
    raises_naming("realizations", gr.transport, realizations=0)
    raises_naming("resume", gr.transport, N=21, realizations=2, T=1e-4, fit=(2e-5, 1e-4), resume=True)
    raises_naming("resume", gr.transport, N=21, realizations=2, T=1e-4, fit=(2e-5, 1e-4), resume=True,
                  checkpoint=str(tmp_path / "none"))
    raises_naming("chains", gr.exponent_table, chains=["A", "B"])
    raises_naming("ic", gr.exponent_table, ic=["kick"])
    raises_naming("F0", gr.exponent_table, F0=[-1.0])


def test_beyond_the_paper_keywords():
    """damping_time, kk_gamma, mle, renormalize, deviation_samples: the tools' rules, told by keyword."""
    c = gr.anderson(N=21)
    raises_naming("damping_time", gr.spreading, c, damping_time=-1e-3)
    raises_naming("damping_time", gr.spreading, c, damping_time=NAN)
    raises_naming("kk_gamma", gr.spreading, c, kk_gamma=-1e-6)
    raises_naming("kk_gamma", gr.spreading, c, kk_gamma=INF)
    raises_naming("renormalize", gr.spreading, c, mle=True, renormalize=0)
    raises_naming("renormalize", gr.spreading, c, mle=True, renormalize=-3)
    raises_naming("deviation_samples", gr.spreading, c, deviation_samples=5)  # needs mle=True
    raises_naming("deviation_samples", gr.spreading, c, mle=True, deviation_samples=1)
    raises_naming("deviation_samples", gr.spreading, c, mle=True, deviation_samples=-2)
    raises_naming("mle", gr.spreading, c, mle=True, kk_gamma=1e-6)  # the tangent map is of the conservative flow
    raises_naming("integrator", gr.spreading, c, mle=True, integrator="reference")
    raises_naming("damping_time", gr.transport, N=21, damping_time=-1.0)
    raises_naming("renormalize", gr.transport, N=21, mle=True, renormalize=0)
    raises_naming("kk_gamma", gr.exponent_table, kk_gamma=NAN)
    raises_naming("renormalize", gr.exponent_table, mle=True, renormalize=0)


def test_file_errors_are_os_errors(tmp_path):
    with pytest.raises(OSError):
        gr.transport(N=21, realizations=2, T=1e-4, fit=(2e-5, 1e-4), checkpoint="/nonexistent-folder/checkpoint")
    with pytest.raises(FileNotFoundError):
        gr.read_radii(str(tmp_path / "missing.radii"))
    bad = tmp_path / "bad.types"
    bad.write_text("1\n3\n")
    raises_naming(str(bad), gr.read_types, str(bad))


def test_numerical_failures_raise_granular_numerical_error():
    assert issubclass(gr.NumericalError, RuntimeError)
    # dt stable but too coarse for this kick: the energy guard trips (a NumericalError, not garbage)
    with pytest.raises(gr.NumericalError, match="energy"):
        gr.spreading(gr.anderson(N=21), alpha=5e-6, dt=5e-6, T=1e-2, fit=(4e-3, 1e-2), fit_step=1e-4,
                     max_energy_error=1e-6)
    # dt past the stability limit is refused before the run, naming the largest stable step
    with pytest.raises(ValueError, match=r"dt 1e-04 s: past the stability limit.*largest stable time step"):
        gr.spreading(gr.anderson(N=21), alpha=5e-6, dt=1e-4, T=1e-2, fit=(4e-3, 1e-2), fit_step=1e-4)
    # also with the default fit_step (1e-5 s, no whole number of 1e-4 s steps): dt is what to mend first
    with pytest.raises(ValueError, match=r"^dt 1e-04 s: past the stability limit"):
        gr.spreading(gr.anderson(N=21), alpha=5e-6, dt=1e-4, T=1e-2)
