"""Figures of two-dimensional crystals: the IPR of every computed mode against its frequency, beside one
mode's bead displacements drawn as arrows on the packing."""
import os

import numpy as np

from . import _io
from ._style import figure, style


def _crystal_data(source):
    """(freq_khz, ipr, x, y, vectors or None, metadata) of a granular.Crystal or the crystal tool's CSV (with
    PREFIX-modes.csv beside it when the run had --vectors)."""
    if _io.is_path(source):
        rows = _io.read_csv(source)
        meta = _io.read_json_beside(source)
        modes_path = os.fspath(source)[: -len(".csv")] + "-modes.csv"
        x = y = vectors = None
        if os.path.exists(modes_path):
            m = _io.read_csv(modes_path)
            beads = int(m["bead"].max())
            x, y = m["x"][:beads], m["y"][:beads]
            vectors = np.stack([m["ux"], m["uy"]], axis=1).reshape(-1, beads, 2)
        return rows["freq_khz"], rows["ipr"], x, y, vectors, meta
    return source.freq_khz, source.ipr, source.x, source.y, source.vectors, source.metadata


def crystal(source, mode=None):
    """The modes of a 2D crystal: IPR against frequency (log scale; 1/N, an extended mode's floor, dashed),
    with the level-spacing ratio <r> in the title; beside it, when the displacements are there, mode `mode`
    (counting from 1 among those computed; None: the most localized) as arrows on the packing.

    source: a granular.Crystal (vectors=True for the second panel) or the crystal tool's CSV (PREFIX-modes.csv
    beside it from --vectors).
    """
    freq, ipr, x, y, vectors, meta = _crystal_data(source)
    p = meta.get("parameters", {})
    beads = meta.get("packing", {}).get("beads", len(x) if x is not None else None)
    with style():
        fig = figure(10.5 if vectors is not None else 5.2, 4.4)
        axes = fig.subplots(1, 2 if vectors is not None else 1, squeeze=False)[0]
        ax = axes[0]
        ax.semilogy(freq, ipr, ".", ms=3, color="C0")
        if beads:
            ax.axhline(1 / beads, ls="--", color="0.5", lw=0.8, label="1/N")
            ax.legend(loc="upper left", frameon=False)
        ax.set_xlabel("frequency f [kHz]")
        ax.set_ylabel("IPR (displacements)")
        r = meta.get("spectrum", {}).get("spacing_ratio")
        title = f"{p.get('lattice', '')} {p.get('Lx', '')} x {p.get('Ly', '')}, {p.get('disorder', '')} w = {p.get('width', '')}"
        ax.set_title(title + (f"\n<r> = {r:.3f} (Poisson 0.386, GOE 0.531)" if r is not None else ""), fontsize=10)
        if vectors is not None:
            k = int(np.argmax(ipr)) if mode is None else int(mode) - 1
            if not 0 <= k < len(vectors):
                raise ValueError(f"mode {mode}: the run has modes 1..{len(vectors)}")
            u = vectors[k]
            scale = 0.9 * np.min(np.hypot(np.diff(x[:2]), np.diff(y[:2]))) / max(np.max(np.hypot(*u.T)), 1e-300)
            ax2 = axes[1]
            ax2.scatter(x * 1e3, y * 1e3, s=4, color="0.75")
            ax2.quiver(x * 1e3, y * 1e3, u[:, 0] * scale * 1e3, u[:, 1] * scale * 1e3, angles="xy", scale_units="xy",
                       scale=1, width=0.003, color="C3")
            ax2.set_aspect("equal")
            ax2.set_xlabel("x [mm]")
            ax2.set_ylabel("y [mm]")
            ax2.set_title(f"mode {k + 1}: f = {freq[k]:.3f} kHz, IPR = {ipr[k]:.3f}", fontsize=10)
    return fig


class _MapFromCsv:
    """The crystal-ipr-map tool's CSV (width,freq_lo_khz,freq_hi_khz,modes,ipr,ratio,ratios; its JSON beside it)
    as a granular.CrystalIprMap's arrays: widths x bins, NaN (modes 0) past a width's top bin."""

    def __init__(self, path):
        rows = _io.read_csv(path)
        if "ratios" not in rows:
            raise ValueError(f"{path}: no ratios column (a crystal-ipr-map CSV?)")
        self.metadata = _io.read_json_beside(path)
        self.width = np.unique(rows["width"])
        lo = np.unique(rows["freq_lo_khz"])
        step = rows["freq_hi_khz"][0] - rows["freq_lo_khz"][0]
        self.freq_lo_khz, self.freq_hi_khz = lo, lo + step
        shape = (len(self.width), len(lo))
        self.modes, self.ratios = np.zeros(shape, dtype=np.int64), np.zeros(shape, dtype=np.int64)
        self.ipr, self.ratio = np.full(shape, np.nan), np.full(shape, np.nan)
        i = np.searchsorted(self.width, rows["width"])
        j = np.searchsorted(lo, rows["freq_lo_khz"])
        self.modes[i, j], self.ratios[i, j] = rows["modes"], rows["ratios"]
        self.ipr[i, j], self.ratio[i, j] = rows["ipr"], rows["ratio"]


def crystal_ipr_map(result):
    """The 2D IPR map: the mean vector IPR against frequency, one curve per disorder width, beside the
    level-spacing ratio <r> per frequency bin with the Poisson (localized) and GOE (extended) values dashed.

    result: a granular.CrystalIprMap or the crystal-ipr-map tool's CSV (its JSON beside it)."""
    if _io.is_path(result):
        result = _MapFromCsv(result)
    centre = 0.5 * (result.freq_lo_khz + result.freq_hi_khz)
    p = result.metadata.get("parameters", {})
    with style():
        fig = figure(10.5, 4.2)
        ax_ipr, ax_r = fig.subplots(1, 2, sharex=True)
        for i, w in enumerate(result.width):
            some = result.modes[i] > 0
            ax_ipr.semilogy(centre[some], result.ipr[i][some], "o-", ms=3, label=f"w = {w:g}")
            enough = result.ratios[i] >= 20  # fewer ratios than this: noise, not statistics
            ax_r.plot(centre[enough], result.ratio[i][enough], "o-", ms=3, label=f"w = {w:g}")
        for value, name in ((0.3863, "Poisson"), (0.5307, "GOE")):
            ax_r.axhline(value, ls="--", color="0.5", lw=0.8)
            ax_r.text(centre[0], value, f" {name}", va="bottom", fontsize=8, color="0.4")
        ax_ipr.set_xlabel("frequency f [kHz]")
        ax_ipr.set_ylabel("mean IPR (displacements)")
        ax_r.set_xlabel("frequency f [kHz]")
        ax_r.set_ylabel("<r> (bins with >= 20 ratios)")
        ax_ipr.legend(frameon=False, fontsize=8)
        fig.suptitle(f"{p.get('lattice', '')} {p.get('Lx', '')} x {p.get('Ly', '')}, {p.get('disorder', '')} disorder, "
                     f"{p.get('realizations', '')} realizations per width", fontsize=11)
    return fig
