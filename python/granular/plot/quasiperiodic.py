"""Figures of quasiperiodic chains: the Hofstadter butterfly and the box-counting dimension of its spectra."""
import numpy as np
from matplotlib.colors import LogNorm

from . import _io
from ._style import figure, quasi_title, style, wrapped_suptitle


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
        title = f"{quasi_title(quasi, ratio=False)}, N = {n}, $F_0$ = {chain.get('F0_N', '?')} N"
        wrapped_suptitle(fig, title)
    return fig


def _dynamical_data(source):
    """(ratios, freq_khz, power[ratio, freq], metadata) from a granular.DynamicalButterfly or the CSV of
    `butterfly --from dynamics` (its JSON beside it)."""
    if not _io.is_path(source):
        return np.asarray(source.ratios), np.asarray(source.freq_khz), np.asarray(source.power), source.metadata
    columns = _io.read_csv(source)
    if "power" not in columns:
        raise ValueError(f"{source}: not a butterfly --from dynamics CSV (no power column)")
    ratio = columns["ratio"]
    ratios, first = np.unique(ratio, return_index=True)
    ratios = ratio[np.sort(first)]
    n = len(ratio) // len(ratios)
    return ratios, columns["freq_khz"][:n], columns["power"].reshape(len(ratios), n), _io.read_json_beside(source)


def _edges(centres):
    """Cell edges around sorted centres (midpoints; the outer cells as wide as their neighbours)."""
    c = np.asarray(centres, dtype=float)
    if len(c) == 1:
        return np.array([c[0] - 0.5, c[0] + 0.5])
    mid = (c[1:] + c[:-1]) / 2
    return np.concatenate([[2 * c[0] - mid[0]], mid, [2 * c[-1] - mid[-1]]])


def dynamical_butterfly(source, eigen=None, ratio=None, floor=1e-6, fmax_khz=None, zoom_khz=None):
    """The Hofstadter butterfly from the dynamics: the velocities' power summed over beads against frequency and
    the ratio beta (log colour scale from `floor` to 1, each beta normalized to max 1), and beside it the power of
    one beta (the one nearest `ratio`; default the golden mean's conjugate 0.618 when in range, else the middle)
    against frequency. eigen: a granular.Butterfly or the butterfly tool's (eigen) CSV of the same chain, whose
    eigenfrequencies are drawn over both panels (dots on the map, ticks on the line). source: a
    granular.DynamicalButterfly or the CSV of `butterfly --from dynamics`. fmax_khz: top of the frequency axis
    [kHz] (default: just above the highest eigenfrequency, else the highest frequency with power above floor).
    zoom_khz: (lo, hi) [kHz], the frequency range of the right panel (default: the map's)."""
    ratios, freq, power, meta = _dynamical_data(source)
    modes = None
    if eigen is not None:
        e_ratio, e_freq, *_ = _butterfly_data(eigen)
        modes = (np.asarray(e_ratio, dtype=float), np.asarray(e_freq, dtype=float))
    if fmax_khz is None:
        if modes is not None and len(modes[1]):
            fmax_khz = 1.05 * float(np.max(modes[1]))
        else:
            above = np.nonzero(np.max(power, axis=0) > floor)[0]
            fmax_khz = float(freq[above[-1]]) * 1.05 if len(above) else float(freq[-1])
    order = np.argsort(ratios)
    if ratio is None:
        ratio = 0.618 if ratios.min() <= 0.618 <= ratios.max() else ratios[order[len(order) // 2]]
    pick = int(np.argmin(np.abs(ratios - ratio)))
    chain = meta.get("chain", {})
    quasi = chain.get("quasiperiodic", {})
    spectrum = meta.get("spectrum", {})
    with style():
        fig = figure(12, 5)
        left, right = fig.subplots(1, 2, gridspec_kw={"width_ratios": [3, 1.4]})
        shown = freq <= fmax_khz
        mesh = left.pcolormesh(_edges(ratios[order]), _edges(freq[shown]),
                               np.clip(power[order][:, shown].T, floor, None), cmap="magma",
                               norm=LogNorm(vmin=floor, vmax=1), rasterized=True, shading="flat")
        fig.colorbar(mesh, ax=left, label="power summed over beads (max 1 per $\\beta$)")
        if modes is not None:
            left.scatter(modes[0], modes[1], s=0.5, marker=".", lw=0, color="cyan", alpha=0.8, rasterized=True,
                         label="eigenfrequencies")
            left.legend(loc="upper right", markerscale=12)
        left.set_xlabel(r"incommensurate ratio $\beta$")
        left.set_ylabel("frequency f [kHz]")
        left.set_ylim(0, fmax_khz)
        right.semilogy(freq[shown], np.clip(power[pick][shown], floor, None), color="k", lw=0.8,
                       label="from the dynamics")
        if modes is not None:
            at = modes[1][np.isclose(modes[0], ratios[pick], rtol=0, atol=1e-12)]
            for k, f in enumerate(at):
                right.axvline(f, color="C0", lw=0.5, alpha=0.6, label="eigenfrequencies" if k == 0 else None)
            right.legend(loc="lower left")
        right.set_ylim(floor, 2)
        right.set_xlim(*(zoom_khz if zoom_khz is not None else (0, fmax_khz)))
        right.set_xlabel("frequency f [kHz]")
        right.set_ylabel("power")
        right.set_title(rf"$\beta$ = {ratios[pick]:.4g}")
        resolution = spectrum.get("resolution_khz")
        title = (f"{quasi_title(quasi, ratio=False)}, N = {chain.get('N', '?')}, $F_0$ = {chain.get('F0_N', '?')} N: "
                 "spectrum of the dynamics"
                 + (f" (resolution {resolution:.3g} kHz)" if resolution else ""))
        wrapped_suptitle(fig, title)
    return fig
