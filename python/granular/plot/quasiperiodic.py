"""Figures of quasiperiodic chains: the Hofstadter butterfly and the box-counting dimension of its spectra."""
import numpy as np
from matplotlib.colors import LogNorm

from . import _io
from ._style import figure, style


def _butterfly_data(source):
    """(ratio, freq_khz, ipr, ratios, dimension, dimension_error, metadata) from a granular.Butterfly or the
    butterfly tool's CSV (its JSON beside it)."""
    if _io.is_path(source):
        columns = _io.read_csv(source)
        meta = _io.read_json_beside(source)
        box = meta.get("box_counting", {})
        return (columns["ratio"], columns["freq_khz"], columns["ipr"], np.asarray(box.get("ratio", [])),
                np.asarray(box.get("dimension", [])), np.asarray(box.get("error", [])), meta)
    return (source.ratio, source.freq_khz, source.ipr, source.ratios, source.dimension, source.dimension_error,
            source.metadata)


def butterfly(source):
    """The Hofstadter butterfly: every mode's frequency against the ratio beta, coloured by its IPR (log scale:
    dark = extended, bright = localized), and the box-counting dimension of each beta's spectrum with its
    standard error beside it. source: a granular.Butterfly or the butterfly tool's CSV."""
    ratio, freq, ipr, ratios, dimension, error, meta = _butterfly_data(source)
    chain = meta.get("chain", {})
    quasi = chain.get("quasiperiodic", {})
    with style():
        fig = figure(10, 5)
        left, right = fig.subplots(1, 2, sharey=False, gridspec_kw={"width_ratios": [3, 1.2]})
        n = chain.get("N") or 100
        points = left.scatter(ratio, freq, c=ipr, s=min(4.0, max(0.6, 60000 / max(len(freq), 1))), marker=".", lw=0,
                              cmap="viridis", norm=LogNorm(vmin=max(np.min(ipr), 1e-4), vmax=1), rasterized=True)
        fig.colorbar(points, ax=left, label="mode IPR")
        left.set_xlabel(r"incommensurate ratio $\beta$")
        left.set_ylabel("frequency f [kHz]")
        left.set_xlim(np.min(ratio), np.max(ratio))
        if len(ratios):
            right.errorbar(ratios, dimension, yerr=error, fmt=".", ms=3, lw=0.6, color="C3")
            right.set_xlabel(r"$\beta$")
            right.set_ylabel("box-counting dimension of the spectrum")
            right.set_ylim(0, 1.05)
        title = (f"{quasi.get('kind', '?')} chain, N = {n}, modulation {quasi.get('modulation', '?')}, "
                 f"F0 = {chain.get('F0_N', '?')} N")
        fig.suptitle(title, fontsize=11)
    return fig
