"""granular.spectrum, SpectrumSolver, DynamicalMatrix and band_edges: keywords, defaults and docstrings. The
matrices and solvers are granular._core's (the library's), frequencies in kHz as the tools give them."""
import operator
import threading

import numpy as np

from . import _core
from ._arguments import double_vector
from ._schema import TableKeywords, split_keywords, with_keywords

from ._core import DynamicalMatrix
from ._model import _C, _document, paper_r1, steel

_SELECTION_DOC = """\
    near, count: the `count` modes nearest `near` [kHz] in frequency (both or neither)
    window: (lo, hi) [kHz]: every mode with lo <= f <= hi (may be empty)
"""
# The solver's keywords: the rows of the library's table over SpectrumConfig (spectrum_parameters(): method, driver,
# vectors, tolerance, subspace, lanes), with its own C++ defaults and help.
_SOLVER = TableKeywords(_core.SpectrumConfig())

_document(DynamicalMatrix, "The symmetric tridiagonal dynamical matrix D = M^(-1/2) K M^(-1/2) [1/s^2] of a chain "
          "(docs/physics.md, 'The linear spectrum'): eigenvalues omega^2, eigenvectors w; the displacement mode is v = w * inverse_sqrt_mass. "
          "Arrays are read-only views.\n\nDynamicalMatrix(diagonal, off_diagonal, inverse_sqrt_mass=None): a matrix "
          "of your own: diagonal (N) and off_diagonal (N-1) [1/s^2], and m^(-1/2) (N) [kg^(-1/2)] for the "
          "displacement IPRs (default 1: the IPR of w itself). Any 1-D array-likes; NaN/inf are refused.",
          N="rows", diagonal="D(i, i) = (B_i + B_(i+1)) / m_i [1/s^2], N entries",
          off_diagonal="D(i, i+1) = -B_(i+1) / sqrt(m_i m_(i+1)) [1/s^2], N-1 entries",
          inverse_sqrt_mass="m_n^(-1/2) [kg^(-1/2)], N entries")
_matrix = DynamicalMatrix.__init__


def _matrix_init(self, diagonal, off_diagonal, inverse_sqrt_mass=None):
    diagonal, off_diagonal = double_vector(diagonal, "diagonal"), double_vector(off_diagonal, "off_diagonal")
    if not diagonal:
        raise ValueError("diagonal: empty (a matrix needs at least one row)")
    if len(off_diagonal) + 1 != len(diagonal):
        raise ValueError(f"off_diagonal: has {len(off_diagonal)} entries; need N - 1 = {len(diagonal) - 1}")
    if inverse_sqrt_mass is None:
        inverse_sqrt_mass = [1.0] * len(diagonal)
    else:
        inverse_sqrt_mass = double_vector(inverse_sqrt_mass, "inverse_sqrt_mass")
        if len(inverse_sqrt_mass) != len(diagonal):
            raise ValueError(f"inverse_sqrt_mass: has {len(inverse_sqrt_mass)} entries; need N = {len(diagonal)}")
        if not all(x > 0 for x in inverse_sqrt_mass):
            raise ValueError("inverse_sqrt_mass: entries must be > 0 [kg^(-1/2)]")
    _matrix(self, diagonal, off_diagonal, inverse_sqrt_mass)


DynamicalMatrix.__init__ = _matrix_init


class Spectrum:
    """Modes of a chain by increasing frequency, as granular.spectrum returns them. Arrays are read-only NumPy views
    of the result (no copies).

    mode: mode numbers 1..N in the full spectrum (int64); omega2: eigenvalues omega^2 of D [1/s^2]; freq_khz:
    frequencies f = omega/2pi [kHz]; ipr: displacement IPR sum v^4 / (sum v^2)^2 of each mode, in (0, 1] (1/N:
    extended, ~1: one bead); residual: per mode |D w - omega^2 w| / max|D_ij| (partial methods; empty for every
    mode); clustered: per mode, True inside a near-degenerate cluster (relative gap < 1e-10 of max omega^2), whose
    IPR depends on the basis chosen inside it (bool); vectors: N x K unit eigenvectors w of D (column j: mode j;
    Fortran order, a view), or None without vectors=True; N: beads of the chain; info: what the solver did (method
    that ran, fallbacks, restarts, candidates, max_residual, clusters); metadata: the spectrum tool's JSON for this
    result (clustered, chain, method, solver, selection, band_edges_khz, version; granular::describe_spectrum, as the
    tool writes it)."""

    def __init__(self, modes, inverse_sqrt_mass, metadata):
        # what _core._SpectrumSolver._solve returns: the result (a _core._Modes), m^(-1/2), the metadata
        for name in ("mode", "omega2", "freq_khz", "ipr", "residual", "N", "info"):
            setattr(self, name, getattr(modes, name))
        self.clustered = modes.clustered.astype(bool)
        self.vectors = modes.vectors.reshape(len(self.omega2), self.N).T if modes.vectors.size else None
        self.metadata, self._inverse_sqrt_mass = metadata, inverse_sqrt_mass
        self.mode.flags.writeable = False

    def displacements(self):
        """N x K displacement modes v = w * m^(-1/2) [kg^(-1/2)] (column j: mode j), or None without vectors"""
        if self.vectors is None:
            return None
        return np.ascontiguousarray(self.vectors * self._inverse_sqrt_mass[:, None])

    def __len__(self):
        return len(self.freq_khz)

    def __repr__(self):
        return f"<granular.Spectrum {len(self)} of {self.N} modes, {self.info['method']}>"


def _selection(near, count, window, got=True):
    """The _core.ModeSelection of the keywords near, count / window (every mode without them), by the library's
    rule (choose_modes) once the window is two numbers; `got`: say how many values a window of the wrong length had."""
    if window is not None:
        window = double_vector(window, "window", False)
        if len(window) != 2:
            raise ValueError("window: expected (lo, hi) in kHz" + (f", got {len(window)} values" if got else ""))
    if count is not None:  # within the library's 64-bit count (no chain has 2^40 modes)
        count = max(min(operator.index(count), 1 << 40), -(1 << 63))
    choices = _core.ModeSelectionChoices()  # the library's (mode_selection_parameters)
    choices.near, choices.count, choices.window = None if near is None else float(near), count, window
    return _core._choose_modes(choices)


def _system(system):
    """(chain, None) for a granular.Chain, (None, matrix) for a granular.DynamicalMatrix (the arguments of
    _core._SpectrumSolver._solve), TypeError otherwise."""
    if not isinstance(system, (_core.Chain, DynamicalMatrix)):
        raise TypeError(f"expected a granular.Chain or a granular.DynamicalMatrix, got {type(system)}")
    return (system, None) if isinstance(system, _core.Chain) else (None, system)


def _config(keywords, function):
    """The _core.SpectrumConfig of the solver keywords (TypeError naming one no row takes)."""
    (given,) = split_keywords(keywords, [_SOLVER], function)
    return _SOLVER.make(given)


class SpectrumSolver(_core._SpectrumSolver):
    __doc__ = ("A spectrum solver that keeps its workspaces between calls: for loops over many chains of one size "
               "(what the IPR map does per thread). solve() gives exactly what granular.spectrum gives.\n\n"
               "SpectrumSolver(**solver keywords): keywords as granular.spectrum's:\n" + _SOLVER.doc())

    def __init__(self, **solver):
        super().__init__(_config(solver, "SpectrumSolver"))
        self._busy = threading.Lock()  # its workspace serves one call at a time

    def solve(self, system, *, near=None, count=None, window=None):
        """The selected modes of a granular.Chain or granular.DynamicalMatrix (near, count / window as
        granular.spectrum's). Returns a granular.Spectrum."""
        system, selection = _system(system), _selection(near, count, window)
        with self._busy:
            return Spectrum(*self._solve(*system, selection, False))


with_keywords(SpectrumSolver.__init__, [_SOLVER], "The solver")


def dynamical_matrix(chain):
    """The dynamical matrix of a chain (ValueError naming F0 at F0 = 0: the sonic vacuum has no linear limit)."""
    return _core._dynamical_matrix(chain)


def frequency_khz(omega2):
    """Frequency f = omega/2pi [kHz] of eigenvalues omega^2 [1/s^2] (a number or an array)."""
    return _core._frequency_khz(omega2)


def omega2_of_khz(khz):
    """omega^2 [1/s^2] of frequencies in kHz (a number or an array)."""
    return _core._omega2_of_khz(khz)


def spectrum(system, *, near=None, count=None, window=None, **solver):
    selection = _selection(near, count, window)
    config = _config(solver, "spectrum")
    return Spectrum(*_core._SpectrumSolver(config)._solve(*_system(system), selection, True))


spectrum.__doc__ = (
    "The linear spectrum of a granular.Chain or granular.DynamicalMatrix (docs/physics.md, 'The linear spectrum'), as the spectrum tool computes "
    "it: every mode by default, or\n" + _SELECTION_DOC +
    "Returns a granular.Spectrum (mode, freq_khz [kHz], ipr, omega2 [1/s^2], residual, vectors; info, metadata). "
    "Releases the GIL while it solves. ValueError names the keyword of a bad value; granular.NumericalError when "
    "every solver failed.")
with_keywords(spectrum, [_SOLVER], "The solver")


class BandEdges:
    """Analytic cut-off frequencies of the ordered chains [kHz] (docs/physics.md, "The linear spectrum"): f1, f2 the tops of the monatomic chains
    of type-1 and type-2 beads; fb1 the diatomic acoustic band top, fb2 and fb3 the optical band's bottom and top."""

    __slots__ = ("f1", "f2", "fb1", "fb2", "fb3")

    def __init__(self, f1, f2, fb1, fb2, fb3):
        self.f1, self.f2, self.fb1, self.fb2, self.fb3 = f1, f2, fb1, fb2, fb3

    def as_dict(self):
        """{'f1': ..., 'f2': ..., 'fb1': ..., 'fb2': ..., 'fb3': ...} in kHz (the tools' band_edges_khz)"""
        return {name: getattr(self, name) for name in self.__slots__}

    def __repr__(self):
        values = ", ".join(f"{name}={_core._format_number(getattr(self, name))}" for name in self.__slots__)
        return f"BandEdges({values}) [kHz]"


def band_edges(xi=_C.xi, F0=_C.F0, R1=paper_r1, material=steel):
    """Band edges [kHz] of beads of radius R1 [m] and xi*R1 of one material under precompression F0 > 0 [N]."""
    return BandEdges(*_core._band_edges(xi, F0, R1, material))
