"""granular: disordered granular chains — linear spectra and Hertzian dynamics — from Python.

The C++ toolkit's library under a Python face (Martínez, Kevrekidis & Porter, PRE 93, 022902 (2016)):
build a chain, get its modes, map localization over disorder, run the nonlinear dynamics and
ensembles. Keywords and units are those of the command-line tools: N, q, xi, seed, realization,
F0 [N], R1 [m], near [kHz], count, window (lo, hi) [kHz], method, threads; arrays are NumPy arrays;
every result carries the metadata dict the tools write as JSON.

    import granular as gr
    chain = gr.anderson(N=100, q=0.5, xi=0.5, seed=1)      # a chain (realization 0 of seed 1)
    modes = gr.spectrum(chain)                              # every mode: freq_khz, ipr
    near = gr.spectrum(chain, near=15.0, count=20, method="bisect")
    grid = gr.ipr_map(disorder="A", xi="0.1:1", q=(0.2, 0.5, 0.8), threads=2, progress=True)
    run = gr.spreading(chain, ic="displacement", T=1e-3, energy_map=True)
    spread = gr.EnergySpread()                              # or observers of your own (gr.Observer)
    gr.spread(chain, gr.velocity_kick(chain, 49, 8e-3), [spread], T=1e-3)   # spread.m2, spread.ipr
    fig = gr.plot.spectrum(modes)                           # figures: granular.plot (matplotlib)

Errors: ValueError naming the keyword of a bad value, OSError for files, granular.NumericalError
when a solver or a guard fails. Long calls release the GIL, take threads=, draw a progress bar with
progress=True and stop on Ctrl-C (KeyboardInterrupt; checkpointed ensembles resume with resume=True).
"""

import os as _os
import sys as _sys

# Bind the extension's ~110 shared libraries (PETSc, SLEPc, MPI, HDF5, ...) lazily, as the
# command-line tools do, instead of Python's default RTLD_NOW: resolving every symbol up front
# cost the import 6-15 ms in our measurements and buys nothing (a missing symbol would be a broken
# install either way).
_dlopen_flags = _sys.getdlopenflags()
try:
    _sys.setdlopenflags((_dlopen_flags & ~_os.RTLD_NOW) | _os.RTLD_LAZY)
    from . import _core
except ImportError as error:  # the figures (granular.plot) work without the compiled part
    _core = None
    _core_error = error
finally:
    _sys.setdlopenflags(_dlopen_flags)

if _core is not None:
    from ._core import NumericalError  # noqa: F401

    NumericalError.__doc__ = ("A numerical method failed: a solver did not converge, a guard tripped (energy error, "
                              "NaN), or every LAPACK driver failed. The message says which and how to replay it.")
    from ._dynamics import exponent_table, spreading, transport  # noqa: F401
    from ._linear import (  # noqa: F401
        BandEdges,
        DynamicalMatrix,
        Spectrum,
        SpectrumSolver,
        band_edges,
        dynamical_matrix,
        frequency_khz,
        omega2_of_khz,
        spectrum,
    )
    from ._model import (  # noqa: F401
        Chain,
        FpuCoefficients,
        Material,
        anderson,
        configuration,
        correlation_theory,
        cyclic_correlation,
        diatomic,
        flat_wall,
        fpu_coefficients,
        from_radii,
        from_types,
        hertz_coefficient,
        homogeneous,
        linear_stiffness,
        nonlinearity_ratio,
        paper_r1,
        quasiperiodic,
        random_chain,
        rdm1,
        rdm2,
        read_radii,
        read_types,
        static_overlap,
        steel,
    )
    from ._observers import (  # noqa: F401
        EnergyMap,
        EnergySpread,
        FinalState,
        Forces,
        Observer,
        RunPlan,
        Snapshot,
        SpectralDensity,
        State,
        displacement_kick,
        spread,
        velocity_kick,
    )
    from ._studies import (  # noqa: F401
        Butterfly,
        Correlations,
        DynamicalButterfly,
        IprMap,
        Localization,
        butterfly,
        correlations,
        dynamical_butterfly,
        ipr_map,
        localization,
    )
    from ._breathers import Breathers, breathers  # noqa: F401
    from ._crystal import Crystal, CrystalIprMap, crystal, crystal_ipr_map  # noqa: F401
    from ._klein_gordon import KleinGordon, klein_gordon  # noqa: F401
    from ._results import ExponentTable, SpreadingRun, Transport  # noqa: F401

    __version__ = _core.__version__
else:
    __version__ = "unknown"


def __getattr__(name):
    if name == "plot":  # granular.plot on first use (it imports matplotlib)
        import importlib

        return importlib.import_module(".plot", __name__)
    if _core is None and not name.startswith("_"):
        raise ImportError(
            f"granular.{name} needs the compiled extension granular._core, which did not load "
            f"({_core_error}). Build it with CMake (option GRANULAR_PYTHON, on by default) and put "
            "build/python on PYTHONPATH, or install with `cmake --install`.")
    raise AttributeError(f"module 'granular' has no attribute {name!r}")


def __dir__():
    return sorted(globals())
