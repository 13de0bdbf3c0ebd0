"""Figures of the linear modes: one chain's spectrum (frequency and IPR of every mode), the ensemble's
IPR map over (xi, mode number), the modes nearest a frequency for growing N."""
import os

import numpy as np
from matplotlib.colors import LogNorm

from . import _io
from ._style import EDGE_LABELS, chain_title, figure, log_ticks, mark_edges, style


# The disorders' names in panel titles (q: the probability of each's first choice, docs/physics.md).
KIND_NAMES = {"A": "Anderson (A)", "RDM1": "random dimer RDM1", "RDM2": "random dimer RDM2", "h": "homogeneous"}


def _ipr_map_data(source):
    if _io.is_path(source):
        rows = _io.read_csv(source)
        if "realization" in rows:
            raise ValueError(f"{os.fspath(source)}: a partial (near/window) map; plot it with partial_spectrum_ipr")
        if "freq_lo_khz" in rows:
            raise ValueError(f"{os.fspath(source)}: a frequency-binned map (--bin-khz); this figure is by mode number")
        meta = _io.read_json_beside(source).get("parameters", {})
        qs = sorted(set(rows["q"]))
        xis = sorted(set(rows["xi"]))
        n = int(rows["mode"].max())
        ipr = np.full((len(qs), len(xis), n), np.nan)
        freq = np.full_like(ipr, np.nan)
        qi = {q: i for i, q in enumerate(qs)}
        xj = {x: j for j, x in enumerate(xis)}
        for q, x, k, f, p in zip(rows["q"], rows["xi"], rows["mode"], rows["freq_khz"], rows["ipr"]):
            ipr[qi[q], xj[x], int(k) - 1] = p
            freq[qi[q], xj[x], int(k) - 1] = f
        disorder = rows["disorder"][0]
        return disorder, np.array(qs), np.array(xis), freq, ipr, meta
    if getattr(source, "selection", False):
        raise ValueError("a partial (near/window) IPR map; plot it with partial_spectrum_ipr")
    if getattr(source, "bin_khz", 0) > 0:
        raise ValueError("a frequency-binned IPR map (bin_khz); this figure is by mode number")
    meta = source.metadata.get("parameters", {})
    return source.disorder, source.q, source.xi, source.freq_khz, source.ipr, meta


def ipr_map(source, band_edges=True, log_color=False):
    """Mean IPR over the size ratio xi and the mode number, one panel per q (the paper's Fig. 4).

    source: a granular.IprMap (every mode) or the ipr-map tool's CSV. band_edges: draw where the mean
    mode frequency crosses f1 (the top of the type-1 band) and fb1 (the diatomic acoustic top) —
    the frequencies above which type-1 and mixed stretches stop carrying waves. log_color: IPR on a
    logarithmic colour scale (extended modes ~1/N and localized ones ~1 both resolved).
    """
    disorder, qs, xis, freq, ipr, meta = _ipr_map_data(source)
    n = ipr.shape[2]
    with style():
        fig = figure(3.9 * len(qs) + 1.2, 4.2)
        axes = fig.subplots(1, len(qs), sharey=True, squeeze=False)[0]
        vmax = np.nanmax(ipr)
        norm = LogNorm(vmin=max(np.nanmin(ipr), 1e-3), vmax=vmax) if log_color else None
        step = xis[1] - xis[0] if len(xis) > 1 else 0.01
        x_edges = np.concatenate([xis - step / 2, [xis[-1] + step / 2]])
        y_edges = np.arange(n + 1) + 0.5
        edge_lines = {}
        if band_edges and meta.get("F0_N") and len(xis) > 1:
            for name in ("f1", "fb1"):
                values = [_io.band_edges_khz(x, meta["F0_N"], meta.get("R1_m")) for x in xis]
                if all(v is not None for v in values):
                    edge_lines[name] = np.array([v[name] for v in values])
        for ax, q, cell_ipr, cell_freq in zip(axes, qs, ipr, freq):
            image = ax.pcolormesh(x_edges, y_edges, cell_ipr.T, shading="flat", cmap="viridis", norm=norm,
                                  vmin=None if log_color else 0, vmax=None if log_color else vmax,
                                  rasterized=True)
            for (name, edge), ls in zip(edge_lines.items(), ("--", ":")):
                # the mode number where the mean frequency first exceeds the edge, at each xi
                crossing = [np.searchsorted(np.nan_to_num(cell_freq[j], nan=np.inf), edge[j]) + 0.5
                            for j in range(len(xis))]
                ax.plot(xis, crossing, ls=ls, color="white", lw=1.3, label=f"mean f = {EDGE_LABELS[name]}")
            # what the panel shows, and its scale: the IPR has no unit (1/N for a mode spread over
            # the chain, 1 for a mode on one bead)
            ax.set_title(f"{KIND_NAMES.get(disorder, disorder)}, q = {q:g}\n"
                         r"mean IPR $\langle P^{-1}\rangle$ (no unit: 1/N to 1)", fontsize=10)
            ax.set_xlabel(r"size ratio $\xi = R_2/R_1$")
            ax.set_xlim(x_edges[0], x_edges[-1])
        axes[0].set_ylabel("mode number (by increasing frequency)")
        if edge_lines:
            axes[0].legend(loc="upper left", fontsize=9, labelcolor="white")
        fig.colorbar(image, ax=list(axes), label=r"mean IPR $\langle P^{-1}\rangle$", pad=0.02)
        if meta:
            fig.suptitle(f"N = {meta.get('N')} beads, $F_0$ = {meta.get('F0_N'):g} N, {meta.get('realizations')} "
                         f"realizations (seed {meta.get('seed')})", fontsize=11)
    return fig


def spectrum(source, band_edges=True):
    """One chain's spectrum: frequency versus mode number, and each mode's IPR beside it on a
    shared frequency axis, band edges dashed (the paper's Fig. 3). source: a granular.Spectrum or
    the spectrum tool's CSV."""
    mode, freq, ipr, meta = _io.spectrum_data(source)
    n = meta.get("chain", {}).get("N")
    with style():
        fig = figure(9, 4.6)
        left, right = fig.subplots(1, 2, sharey=True, gridspec_kw={"width_ratios": [3, 2]})
        left.plot(mode, freq, ".", ms=4, color="C0")
        left.set_xlabel("mode number")
        left.set_ylabel("frequency f [kHz]")
        right.scatter(ipr, freq, s=10, color="C3")
        right.set_xscale("log")
        log_ticks(right.xaxis)
        right.set_xlabel(r"mode IPR $P^{-1} = \sum v^4 / (\sum v^2)^2$")
        if n:
            right.axvline(1.5 / (n + 1), color="0.5", lw=1.0, ls=":", label=r"$3/2(N+1)$: a plane wave")
            right.legend(loc="lower right", fontsize=9)
        if band_edges:
            edges = meta.get("band_edges_khz", {})
            lo, hi = np.min(freq), np.max(freq)
            span = hi - lo if hi > lo else 1.0
            shown = {k: v for k, v in edges.items() if lo - 0.3 * span <= v <= hi + 0.3 * span}
            for value in shown.values():
                left.axhline(value, ls="--", lw=0.9, color="0.35", zorder=0.5)
            left.set_ylim(*left.get_ylim())
            mark_edges(right, shown)  # labelled on the right
        title = chain_title(meta.get("chain", {}))
        if "selection" in meta:
            sel = meta["selection"]
            title += (f" — {sel['count']} modes nearest {sel['near_khz']:g} kHz" if "near_khz" in sel
                      else f" — modes in {sel['window_khz'][0]:g}–{sel['window_khz'][1]:g} kHz")
        if title:
            fig.suptitle(title, fontsize=11)
    return fig


def partial_spectrum_ipr(spectra, near=None, labels=None):
    """IPR versus f - f0 of the modes nearest f0 for chains of growing N: extended modes fall as
    3/(2N) (dotted), localized ones keep an N-independent IPR. spectra: granular.Spectrum results
    (near=..., count=...) or spectrum-tool CSVs, one per N."""
    import matplotlib.cm

    with style():
        fig = figure(7.5, 4.8)
        ax = fig.subplots()
        colours = matplotlib.cm.viridis(np.linspace(0, 0.9, max(len(spectra), 1)))
        f0 = near
        for i, (source, colour) in enumerate(zip(spectra, colours)):
            _, freq, ipr, meta = _io.spectrum_data(source)
            n = meta.get("chain", {}).get("N")
            if f0 is None:
                f0 = meta.get("selection", {}).get("near_khz", float(np.median(freq)))
            label = labels[i] if labels else (f"N = {n:g}" if n else f"set {i + 1}")
            ax.semilogy(np.asarray(freq) - f0, ipr, "o", ms=5, color=colour, label=label)
            if n:
                ax.axhline(1.5 / n, color=colour, lw=0.8, ls=":")
        ax.set_xscale("symlog", linthresh=1e-5)
        log_ticks(ax.yaxis)
        ax.set_xlabel(f"f − {f0:g} kHz [kHz] (symmetric log scale)")
        ax.set_ylabel(r"mode IPR $P^{-1}$")
        ax.set_title("modes nearest a frequency (dotted: 3/(2N), an extended mode)")
        ax.legend()
    return fig


def _ipr_cell(source, q, xi):
    """The rows of one (q, xi) cell of an ipr-map result or CSV (by mode or in frequency bins), the
    disorder, q and xi (None: the map's only value)."""
    if _io.is_path(source):
        rows, name = _io.read_csv(source), os.fspath(source)
        disorder = rows["disorder"][0]
    else:
        rows, name, disorder = source.rows(), "this IPR map", source.disorder
    qs, xis = np.asarray(rows["q"], float), np.asarray(rows["xi"], float)
    for what, values, chosen in (("q", qs, q), ("xi", xis, xi)):
        if chosen is None and len(set(values)) > 1:
            raise ValueError(f"{name}: several values of {what} ({', '.join(f'{v:g}' for v in sorted(set(values)))}); "
                             f"choose one ({what}=)")
    q = qs[0] if q is None else q
    xi = xis[0] if xi is None else xi
    pick = (np.abs(qs - q) < 1e-12) & (np.abs(xis - xi) < 1e-12)
    if not pick.any():
        raise ValueError(f"{name}: no rows with q = {q}, xi = {xi}")
    return {k: np.asarray(v)[pick] for k, v in rows.items()}, disorder, q, xi


def ipr_averaging(by_mode, binned, q=None, xi=None, gap_khz=None):
    """The two averagings of ipr-map for one (q, xi) cell: the ensemble's IPR against frequency f
    [kHz] averaged by mode number (each mode number's mean f and mean IPR over the realizations:
    points) and in frequency bins (the mean IPR of every mode of every realization in the bin:
    steps), with the number of modes per bin below. Averaged by mode number, points fall inside band
    gaps where no chain has a mode (the realizations number their modes differently); the bins do not.

    by_mode: a granular.IprMap averaged by mode number or the ipr-map tool's CSV (columns disorder,
    q, xi, mode, freq_khz, ipr). binned: the same map with bin_khz > 0 (ipr-map --bin-khz; columns
    disorder, q, xi, freq_lo_khz, freq_hi_khz, modes, ipr). q, xi: the cell (default: the map's
    only value). gap_khz: (lo, hi) [kHz], a band gap to shade (e.g. fb1, fb2 of the diatomic chain).
    """
    cell, disorder, q, xi = _ipr_cell(by_mode, q, xi)
    bins, _, _, _ = _ipr_cell(binned, q, xi)
    if "mode" not in cell or "realization" in cell or "freq_lo_khz" not in bins:
        raise ValueError("ipr_averaging: give the map averaged by mode number (every mode) first, the "
                         "frequency-binned one (--bin-khz) second")
    f_mode, ipr_mode = cell["freq_khz"].astype(float), cell["ipr"].astype(float)
    lo, hi = bins["freq_lo_khz"].astype(float), bins["freq_hi_khz"].astype(float)
    count, ipr_bin = bins["modes"].astype(float), bins["ipr"].astype(float)
    # matplotlib's default look (not style()), as docs/figures/ipr-averaging.png was drawn
    fig = figure(6.4, 5.6)
    top, bottom = fig.subplots(2, 1, sharex=True, height_ratios=[3, 1.3])
    edges = np.append(lo, hi[-1])
    top.stairs(np.where(count > 0, ipr_bin, np.nan), edges, color="tab:blue", lw=1.6,
               label=f"frequency bins of {hi[0] - lo[0]:g} kHz (every mode of every realization)")
    top.plot(f_mode, ipr_mode, "o", ms=3, color="tab:orange", label="by mode number (mean f, mean IPR)")
    bottom.stairs(count, edges, color="tab:blue", fill=True, alpha=0.5)
    if gap_khz is not None:
        for ax in (top, bottom):
            ax.axvspan(*gap_khz, color="0.85", zorder=0,
                       label="gap (fb1, fb2) of the diatomic chain" if ax is top else None)
    top.set_ylabel("IPR")
    top.set_title(f"{disorder}, q = {q:g}, ξ = {xi:g}: the two averagings of ipr-map")
    top.legend(fontsize=8, loc="upper left")
    bottom.set_ylabel("modes per bin")
    bottom.set_xlabel("frequency f [kHz]")
    return fig
