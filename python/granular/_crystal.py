"""granular.crystal: the modes of a two-dimensional granular crystal (docs/crystals.md), the crystal tool as a
call. Its keywords are the rows of the library's crystal_parameters() with CrystalCase's C++ defaults (_schema.py):
nothing here repeats a default or a help line."""
import numpy as np

from . import _core
from ._results import Result
from ._schema import TableKeywords, split_keywords, with_keywords

_CASE = TableKeywords(_core.CrystalCase())


class Crystal(Result):
    """The modes of a 2D granular crystal (granular.crystal), as the crystal tool writes them.

    freq_khz, omega2 [1/s^2], ipr: per computed mode by increasing omega^2 (every mode, or the count nearest
    `near`); vectors: None, or (modes x beads x 2) bead displacements u = M^-1/2 w of the unit eigenvectors
    [kg^-1/2]; x, y [m]: the beads' reference centres; mass [kg], radius [m] per bead; spacing_ratio: <r> of the
    frequencies in the ratio window (Poisson 0.3863, GOE 0.5307) over ratios_averaged ratios; method ('lapack' or
    'slepc'); imbalance: the static state's largest relative force imbalance; metadata: the tool's JSON.
    """


def crystal(**keywords):
    """The linear modes of a 2D granular crystal: Lx x Ly steel beads in a square or hexagonal packing, held by
    four walls pushing with F0 per bead they touch (or periodic under a uniform strain), its static state found by
    Newton on the Hertz contact network, then every mode by dense LAPACK or the `count` modes nearest `near`
    [kHz] by SLEPc shift-invert. A bad value is a ValueError naming its keyword; a packing that is not rigid
    under its load (a compressed square packing's shear instability) is refused. Returns a granular.Crystal."""
    (given,) = split_keywords(keywords, [_CASE], "crystal")
    raw = _core._crystal(_CASE.make(given))
    beads = len(raw["x"])
    vectors = np.asarray(raw["vectors"], dtype=float)
    if vectors.size:  # columns of w, mode-major, to displacements (mode, bead, x|y)
        vectors = vectors.reshape(-1, beads, 2) / np.sqrt(np.asarray(raw["mass"]))[None, :, None]
    raw["vectors"] = vectors if vectors.size else None
    return Crystal(raw)


with_keywords(crystal, [_CASE], "Keywords (the library's crystal_parameters(), with CrystalCase's C++ defaults)")
