"""granular.crystal: the modes of a two-dimensional granular crystal (docs/crystals.md), the crystal tool as a
call. Its keywords are the rows of the library's crystal_parameters() with CrystalCase's C++ defaults (_schema.py):
nothing here repeats a default or a help line."""
import numpy as np

from . import _core
from ._dynamics import _run
from ._results import Result
from ._schema import TableKeywords, split_keywords, with_keywords

_CASE = TableKeywords(_core.CrystalCase())
_MAP = TableKeywords(_core.CrystalIprMapConfig())


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
    if isinstance(keywords.get("window"), (tuple, list)):  # (lo, hi) [kHz]: the row's text form lo:hi
        lo, hi = keywords["window"]
        keywords["window"] = f"{float(lo)!r}:{float(hi)!r}"
    (given,) = split_keywords(keywords, [_CASE], "crystal")
    raw = _core._crystal(_CASE.make(given))
    beads = len(raw["x"])
    vectors = np.asarray(raw["vectors"], dtype=float)
    if vectors.size:  # columns of w, mode-major, to displacements (mode, bead, x|y)
        vectors = vectors.reshape(-1, beads, 2) / np.sqrt(np.asarray(raw["mass"]))[None, :, None]
    raw["vectors"] = vectors if vectors.size else None
    return Crystal(raw)


with_keywords(crystal, [_CASE], "Keywords (the library's crystal_parameters(), with CrystalCase's C++ defaults)")


class CrystalIprMap(Result):
    """The IPR map of disordered 2D crystals (granular.crystal_ipr_map): per disorder width (rows) and frequency
    bin (columns; NaN past a width's top bin).

    width; freq_lo_khz, freq_hi_khz: the bins' edges; modes: the modes of all realizations in each bin; ipr: their
    mean vector IPR; ratio: <r> of the levels in each bin (each realization's ratios pooled), over `ratios` ratios;
    metadata: the map's parameters (its table's rows).
    """


def crystal_ipr_map(*, threads=0, checkpoint=None, resume=False, resume_other_version=False, fresh=False,
                    progress=False, **keywords):
    """The 2D analogue of the paper's IPR map: every mode of `realizations` crystals per disorder width, binned
    in frequency, with the mean vector IPR and the level-spacing ratio <r> in each bin (Poisson 0.3863 for
    localized modes, GOE 0.5307 for extended ones). Every mode by dense LAPACK: crystals of up to a few thousand
    beads. Returns a granular.CrystalIprMap (the crystal-ipr-map tool's numbers for the same keywords).

    threads: crystals solved at once (0: every core); the map does not depend on it
    checkpoint: a file logging each solved crystal (removed once the map is complete); resume=True continues an
        interrupted map from it and gives exactly the uninterrupted map (resume_other_version=True also accepts
        a checkpoint another granular version made); fresh=True discards it and starts again
    progress: draw a progress bar. Releases the GIL; Ctrl-C stops it after the crystals in flight
        (KeyboardInterrupt), leaving the checkpoint to resume from."""
    (given,) = split_keywords(keywords, [_MAP], "crystal_ipr_map")
    run = _run(threads, checkpoint, resume, resume_other_version, progress, fresh)
    raw = _core._crystal_ipr_map(_MAP.make(given), run)
    cells = raw["cells"]
    bins = max(len(c["bin_modes"]) for c in cells)

    def padded(key, dtype=float):
        out = np.full((len(cells), bins), np.nan if dtype is float else 0, dtype=dtype)
        for i, c in enumerate(cells):
            out[i, : len(c[key])] = c[key]
        return out

    edges = np.arange(bins + 1) * raw["bin_hz"] * 1e-3
    return CrystalIprMap(width=np.array([c["width"] for c in cells]), freq_lo_khz=edges[:-1], freq_hi_khz=edges[1:],
                         modes=padded("bin_modes", np.int64), ipr=padded("bin_ipr"), ratio=padded("bin_ratio"),
                         ratios=padded("bin_ratios", np.int64), metadata=raw["metadata"])


with_keywords(crystal_ipr_map, [_MAP], "Keywords (the library's crystal_ipr_map_parameters(): the crystal's rows of "
              "crystal_parameters(), then the map's own)", first=True)
