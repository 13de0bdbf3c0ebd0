"""Figures of granular's results, as a physicist would show them in a talk.

Every function takes a result (what granular.spectrum, ipr_map, spreading, ... return) or the
files the command-line tools write (CSV with its JSON beside it, HDF5 energy maps), and returns a
matplotlib Figure: units on every axis, band edges marked where they matter, sizes that read on a
slide. Save with ``fig.savefig("x.png")``; in a notebook the returned figure is shown.

From a shell, ``python3 -m granular.plot <kind> FILE... [-o out.png]`` draws the same figures
(``python3 -m granular.plot --help`` lists the kinds).

    ipr_map(result_or_csv)                     mean IPR over (xi, mode), one panel per q (paper Fig. 4)
    spectrum(result_or_csv)                    f versus mode and the IPR beside it (paper Fig. 3)
    correlations(results_or_csvs)              rho(d) with its spread and the infinite-chain formula
    partial_spectrum_ipr(spectra)              IPR versus f - f0 of the modes nearest f0, several N
    localization(scan_or_csv, spectra)         localization length l(f) beside the IPR of finite chains
    energy_map(run_or_h5, spectral_density)    E_n(t) beside g(nu), zoomable in t and n
    forces(run_or_csv, profile)                force versus t at chosen beads, force profile at T
    spreading(runs_or_csvs)                    m2(t) and P^-1(t), log-log, with L_d insets
    exponents(table_or_prefix, kick)           the paper's transport panels per chain kind and F0
    centres(table_or_prefix, chain)            m2 about the kicked site beside m2 about the centroid
    paper_comparison(table_or_prefix)          our gamma (both centres) beside the paper's Table I
    profiles(table_or_prefix)                  averaged energy profiles E_n(T)
    spectral_densities(pairs, titles)          g(nu) of the displacements beside that of the velocities
    cost(benchmark_json)                       integrators' cost-accuracy curves
"""
import math
import os

import matplotlib
import numpy as np
from matplotlib.colors import LogNorm

from . import _io
from ._style import EDGE_LABELS, chain_title, figure, guides, log_derivative, log_ticks, mark_edges, style

__all__ = ["ipr_map", "spectrum", "correlations", "partial_spectrum_ipr", "localization", "energy_map", "forces", "spreading",
           "exponents", "centres", "paper_comparison", "profiles", "spectral_densities", "cost"]


# --- the linear spectrum -----------------------------------------------------------------------

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
            ax.set_title(f"{disorder}, q = {q:g}")
            ax.set_xlabel(r"size ratio $\xi = R_2/R_1$")
            ax.set_xlim(x_edges[0], x_edges[-1])
        axes[0].set_ylabel("mode number (by increasing frequency)")
        if edge_lines:
            axes[0].legend(loc="upper left", fontsize=9, labelcolor="white")
        fig.colorbar(image, ax=list(axes), label=r"mean IPR $\langle P^{-1}\rangle$", pad=0.02)
        if meta:
            fig.suptitle(f"N = {meta.get('N')}, $F_0$ = {meta.get('F0_N'):g} N, {meta.get('realizations')} "
                         f"realizations (seed {meta.get('seed')})", fontsize=11)
    return fig


def _spectrum_data(source):
    if _io.is_path(source):
        rows = _io.read_csv(source)
        meta = _io.read_json_beside(source)
        return rows["mode"], rows["freq_khz"], rows["ipr"], meta
    return source.mode, source.freq_khz, source.ipr, source.metadata


def spectrum(source, band_edges=True):
    """One chain's spectrum: frequency versus mode number, and each mode's IPR beside it on a
    shared frequency axis, band edges dashed (the paper's Fig. 3). source: a granular.Spectrum or
    the spectrum tool's CSV."""
    mode, freq, ipr, meta = _spectrum_data(source)
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


def correlations(sources, labels=None):
    """Ensemble-mean correlation rho(d) of bead types (error bars: the spread over realizations)
    with the infinite-chain formula. sources: one or several granular.Correlations or CSVs."""
    if not isinstance(sources, (list, tuple)):
        sources = [sources]
    with style():
        fig = figure(6.4, 4.4)
        ax = fig.subplots()
        for i, source in enumerate(sources):
            if _io.is_path(source):
                rows = _io.read_csv(source)
                p = _io.read_json_beside(source).get("parameters", {})
                d, mean, std, theory = rows["distance"], rows["rho_mean"], rows["rho_std"], rows["rho_theory"]
            else:
                p = source.metadata.get("parameters", {})
                d, mean, std, theory = source.distance, source.rho_mean, source.rho_std, source.rho_theory
            label = labels[i] if labels else (f"{p['disorder']}, q = {p['q']:g}" if p else f"set {i + 1}")
            ax.errorbar(d, mean, yerr=std, fmt="o", ms=5, capsize=3, color=f"C{i}", label=f"{label}: mean ± std")
            ax.plot(d, theory, "-", color=f"C{i}", lw=1.2, label=f"{label}: infinite chain")
        ax.axhline(0, color="0.6", lw=0.6)
        ax.set_xlabel("distance d [beads]")
        ax.set_ylabel(r"correlation $\rho(d)$")
        ax.legend()
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
            _, freq, ipr, meta = _spectrum_data(source)
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


def localization(source, spectra=(), finite_N=None):
    """Localization length l(f) = 1/lambda of the infinite chain (transfer matrices, with its
    statistical error) beside the IPR of every mode of finite chains of the same disorder: a mode
    is extended in a finite chain where l(f) exceeds its length. Band edges dashed.

    source: a granular.Localization or the localization tool's CSV. spectra: granular.Spectrum
    results or spectrum CSVs of finite chains (optional). finite_N: their length, drawn as a line
    on the left (default: from the spectra)."""
    if _io.is_path(source):
        rows = _io.read_csv(source)
        meta = _io.read_json_beside(source)
        f, lam, err = rows["freq_khz"], rows["lyapunov"], rows["lyapunov_err"]
    else:
        meta = source.metadata
        f, lam, err = source.freq_khz, source.lyapunov, source.lyapunov_err
    f, lam, err = (np.asarray(x, float) for x in (f, lam, err))
    with np.errstate(divide="ignore", invalid="ignore"):
        ell = np.where(lam > 0, 1 / lam, np.nan)
        ell_lo = np.where(lam > 0, 1 / (lam + err), np.nan)
        ell_hi = np.where(lam > err, 1 / (lam - err), np.nan)
    modes = [_spectrum_data(s) for s in spectra]
    if finite_N is None and modes:
        finite_N = modes[0][3].get("chain", {}).get("N") or len(modes[0][0])
    with style():
        fig = figure(11, 4.6)
        left, right = fig.subplots(1, 2, sharex=True)
        left.fill_between(f, ell_lo, ell_hi, color="C0", alpha=0.3, lw=0, label="± statistical error")
        left.plot(f, ell, color="C0", lw=1.2, label=r"$\ell = 1/\lambda$ (transfer matrix)")
        left.set_yscale("log")
        log_ticks(left.yaxis)
        left.set_xlabel("frequency f [kHz]")
        left.set_ylabel(r"localization length $\ell$ [beads]")
        if finite_N:
            left.axhline(finite_N, ls=":", color="0.3", lw=1.2, label=f"N = {finite_N} (the finite chains)")
        for _, freq, ipr, _ in modes:
            right.plot(freq, ipr, ".", ms=3, color="C3")
        right.set_yscale("log")
        log_ticks(right.yaxis)
        right.set_xlabel("frequency f [kHz]")
        right.set_ylabel(r"mode IPR $P^{-1}$")
        right.set_title(f"modes of {len(modes)} finite chain(s)" + (f" of {finite_N} beads" if finite_N else "")
                        if modes else "no finite chains given", fontsize=11)
        left.legend(loc="lower left")
        edges = meta.get("band_edges_khz", {})
        left.set_xlim(f.min(), f.max())
        mark_edges(left, edges, orientation="vertical")
        mark_edges(right, edges, orientation="vertical", labels=False)
        title = chain_title(meta.get("chain", {}))
        if title:
            fig.suptitle(title, fontsize=11)
    return fig


# --- the dynamics ----------------------------------------------------------------------------------

def _chain_edges(meta):
    chain = meta.get("parameters", {}).get("chain", {})
    if chain.get("F0_N") and "xi" in chain:
        return _io.band_edges_khz(chain["xi"], chain["F0_N"], chain.get("R1_m")), chain
    return None, chain


def energy_map(source, spectral_density=None, t_window=None, site_window=None, floor=-12.0, band_edges=True):
    """Spatiotemporal energy map log10(E_n / sum E) over bead n and time, beside the spectral
    density g(nu) of the same run with the chain's band edges.

    source: a granular.SpreadingRun made with energy_map=True (and spectral_density=True), or the
    spreading tool's HDF5 energy map. spectral_density: the tool's spectrum CSV (a run carries its
    own). t_window: (t0, t1) [s] and site_window: (n0, n1) [beads, from 1] zoom in. floor: the
    lowest log10 relative energy shown (zeros beyond the front are blank).
    """
    meta = {}
    if _io.is_path(source):
        t, site, energy = _io.read_hdf5_map(source)
    else:
        if source.energy_map is None:
            raise ValueError("this run has no energy map: run granular.spreading(..., energy_map=True)")
        t, site, energy = source.energy_map["t"], source.energy_map["site"], source.energy_map["energy"]
        meta = source.metadata
        if spectral_density is None and source.spectral_density is not None:
            spectral_density = source.spectral_density
    if _io.is_path(spectral_density):
        spectral_density = _io.read_csv(spectral_density)
    t, site, energy = np.asarray(t), np.asarray(site), np.asarray(energy)
    rows = np.ones(len(t), bool) if t_window is None else (t >= t_window[0]) & (t <= t_window[1])
    cols = np.ones(len(site), bool) if site_window is None else (site >= site_window[0]) & (site <= site_window[1])
    if not rows.any() or not cols.any():
        raise ValueError("t_window/site_window select no part of the map")
    total = energy.sum(axis=1, keepdims=True)
    with np.errstate(divide="ignore", invalid="ignore"):
        shown = np.log10(np.where(energy > 0, energy / total, np.nan))
    shown = shown[np.ix_(rows, cols)]
    edges, chain = _chain_edges(meta) if band_edges else (None, {})
    with style():
        if spectral_density is not None:
            fig = figure(11, 5)
            ax, bx = fig.subplots(1, 2, gridspec_kw={"width_ratios": [3, 1.1]})
        else:
            fig = figure(8, 5)
            ax, bx = fig.subplots(), None
        cmap = matplotlib.colormaps["inferno"].copy()
        cmap.set_bad(cmap(0.0))  # no energy at all (beyond the front) looks like the floor
        image = ax.pcolormesh(site[cols], t[rows] * 1e3, shown, shading="nearest", cmap=cmap, vmin=floor,
                              vmax=0, rasterized=True)
        fig.colorbar(image, ax=ax, label=r"$\log_{10}\, E_n / \sum_n E_n$", pad=0.02)
        ax.set_xlabel("bead n")
        ax.set_ylabel("time t [ms]")
        if bx is not None:
            freq, g = np.asarray(spectral_density["freq_khz"]), np.asarray(spectral_density["g"])
            keep = g > 0
            bx.semilogx(g[keep], freq[keep], lw=1.0, color="C0")
            bx.set_xlim(max(g[keep].min(), 1e-8), 1.5)
            log_ticks(bx.xaxis)
            bx.set_xlabel(r"spectral density $g(\nu)$")
            bx.set_ylabel(r"frequency $\nu$ [kHz]")
            # the vibrations live below the highest band edge; above it only the kick's tail
            top = 1.25 * max(edges.values()) if edges else freq[keep][g[keep] > 1e-6 * g.max()].max()
            bx.set_ylim(0, top)
            mark_edges(bx, edges)
        title = chain_title(chain)
        if title:
            fig.suptitle(title, fontsize=11)
    return fig


def forces(source, profile=None, sites=None):
    """Force on chosen beads versus time beside the force profile along the chain at T.

    source: a granular.SpreadingRun made with forces_at=[...] (its final state gives the profile),
    or the spreading tool's PREFIX-forces.csv with profile= its PREFIX-profile.csv (--profile).
    sites: which recorded beads to draw (default all).
    """
    if _io.is_path(source):
        series = _io.read_csv(source)
        recorded = np.unique(series["site"])
        curves = {int(s): (series["t"][series["site"] == s], series["force"][series["site"] == s]) for s in recorded}
        prof = _io.read_csv(profile) if profile is not None else None
        prof_site, prof_force = (prof["site"], prof["force"]) if prof is not None else (None, None)
        meta = {}
    else:
        if source.forces is None:
            raise ValueError("this run recorded no forces: run granular.spreading(..., forces_at=[...])")
        f = source.forces
        curves = {int(s): (f["t"], f["force"][i]) for i, s in enumerate(f["site"])}
        prof_force = source.final_state["force"]
        prof_site = np.arange(1, len(prof_force) + 1)
        meta = source.metadata
    if sites is not None:
        curves = {s: curves[s] for s in sites}
    _, chain = _chain_edges(meta)
    with style():
        fig = figure(11, 4.4)
        ax, bx = fig.subplots(1, 2, gridspec_kw={"width_ratios": [3, 2]})
        for s, (t, force) in curves.items():
            ax.plot(np.asarray(t) * 1e3, force, lw=1.0, label=f"bead {s}")
        ax.set_xlabel("time t [ms]")
        ax.set_ylabel("force on the bead [N]")
        ax.legend()
        if prof_force is not None:
            bx.plot(prof_site, prof_force, lw=0.8, color="0.2")
            bx.set_xlabel("bead n")
            bx.set_ylabel("force at T [N]")
        else:
            bx.set_visible(False)
        title = chain_title(chain)
        if title:
            fig.suptitle(title, fontsize=11)
    return fig


def _spread_curves(source):
    if _io.is_path(source):
        d = _io.read_csv(source)
        meta = _io.read_json_beside(source)
        return d["t"], d["m2"], d["ipr"], meta
    return source["t"], source["m2"], source["ipr"], source["metadata"]


def _inset_ld(ax, curves, where, fit=None, ylim=None):
    """The log derivative L_d(t) of each curve in an inset (the paper's insets)."""
    inset = ax.inset_axes(where)
    for t, y, colour in curves:
        lt, ls = log_derivative(t, y)
        if len(lt):
            inset.semilogx(lt, ls, color=colour, lw=1.0)
    if fit:
        inset.axvspan(fit[0], fit[1], color="0.85", zorder=0)
    if ylim:
        inset.set_ylim(*ylim)
    inset.set_xlabel("t [s]", fontsize=8, labelpad=1)
    inset.set_ylabel(r"$L_d$", fontsize=9, labelpad=1)
    inset.tick_params(labelsize=7, pad=1)
    return inset


def spreading(sources, labels=None):
    """m~2(t) and P^-1(t) on log-log axes for one or several runs or ensembles, with guide slopes
    (m2: 2 ballistic, 1 diffusive; P^-1: -1, 0) and the log derivative L_d in an inset, the fit
    window shaded. sources: granular.SpreadingRun / granular.Transport results or spreading CSVs."""
    if not isinstance(sources, (list, tuple)):
        sources = [sources]
    data = [_spread_curves(s) for s in sources]
    if labels is None:
        labels = []
        for i, (_, _, _, meta) in enumerate(data):
            chain = meta.get("parameters", {}).get("chain", {})
            labels.append(chain.get("disorder", f"run {i + 1}"))
    fit = next((m.get("parameters", {}).get("fit_s") for _, _, _, m in data if m.get("parameters")), None)
    with style():
        fig = figure(11, 4.6)
        ax, bx = fig.subplots(1, 2)
        m2_curves, ipr_curves = [], []
        for i, ((t, m2, ipr, _), label) in enumerate(zip(data, labels)):
            t, m2, ipr = map(np.asarray, (t, m2, ipr))
            keep = t > 0
            ax.loglog(t[keep], m2[keep], color=f"C{i}", label=label)
            bx.loglog(t[keep], ipr[keep], color=f"C{i}", label=label)
            m2_curves.append((t[keep], m2[keep], f"C{i}"))
            ipr_curves.append((t[keep], 1 / ipr[keep], f"C{i}"))
        guides(ax, m2_curves, (2, 1), fit)
        guides(bx, [(t, 1 / y, c) for t, y, c in ipr_curves], (0, -1), fit)
        for axis in (ax, bx):
            log_ticks(axis.xaxis)
            log_ticks(axis.yaxis)
            axis.set_xlabel("time t [s]")
        ax.set_ylabel(r"second moment $\tilde m_2$ [beads$^2$]")
        bx.set_ylabel(r"participation $P^{-1}$")
        _inset_ld(ax, m2_curves, [0.09, 0.6, 0.36, 0.33], fit, ylim=(-0.5, 2.5))
        bx.legend(loc="lower left")
    return fig


def _exponent_data(source):
    if _io.is_path(source):
        prefix = os.fspath(source)
        curves = _io.read_csv(prefix + "-curves.csv")
        profiles_path = prefix + "-profiles.csv"
        profiles = _io.read_csv(profiles_path) if os.path.exists(profiles_path) and os.path.getsize(profiles_path) > 60 \
            else None
        meta = {}
        if os.path.exists(prefix + ".json"):
            import json

            with open(prefix + ".json") as f:
                meta = json.load(f)
        table = _io.read_csv(prefix + ".csv") if os.path.exists(prefix + ".csv") else None
        groups = {}
        for i in range(len(curves["t"])):
            key = (curves["ic"][i], float(curves["F0"][i]), curves["disorder"][i])
            names = ("t", "m2", "m2_centroid", "ipr") if "m2_centroid" in curves else ("t", "m2", "ipr")
            g = groups.setdefault(key, {k: [] for k in names})
            for k in names:
                g[k].append(curves[k][i])
        prof = {}
        if profiles is not None:
            for i in range(len(profiles["site"])):
                key = (profiles["ic"][i], float(profiles["F0"][i]), profiles["disorder"][i])
                prof.setdefault(key, []).append(profiles["energy"][i])
        fits = {}
        if table is not None:
            for i in range(len(table["gamma"])):
                fits[(table["ic"][i], float(table["F0"][i]), table["disorder"][i])] = table["gamma"][i]
        return groups, prof, fits, meta
    groups = {(c["ic"], float(c["F0"]), c["disorder"]): c for c in source["curves"]}
    prof = {(p["ic"], float(p["F0"]), p["disorder"]): p["energy"] for p in source["profiles"]}
    table = source["table"]
    fits = {(ic, float(f0), d): g for ic, f0, d, g in zip(table["ic"], table["F0"], table["disorder"], table["gamma"])}
    return groups, prof, fits, source["metadata"]


def exponents(source, kick="displacement"):
    """The paper's transport figure for one kick: per chain kind, m~2(t) and P^-1(t) of the
    ensemble means on log-log axes, one curve per F0, guide slopes and the log derivative L_d in
    an inset (fit window shaded). source: a granular.ExponentTable or the exponents tool's prefix."""
    groups, _, fits, meta = _exponent_data(source)
    keys = [k for k in groups if k[0] == kick]
    if not keys:
        raise ValueError(f"no {kick!r} kick in these results (kicks: {sorted({k[0] for k in groups})})")
    chains = list(dict.fromkeys(k[2] for k in keys))
    f0s = list(dict.fromkeys(k[1] for k in keys))
    fit = meta.get("parameters", {}).get("fit_s")
    with style():
        fig = figure(10, 3.1 * len(chains) + 0.6)
        axes = fig.subplots(len(chains), 2, squeeze=False, sharex=True)
        for row, chain in enumerate(chains):
            m2_curves, inv_curves = [], []
            for k, f0 in enumerate(f0s):
                g = groups.get((kick, f0, chain))
                if g is None:
                    continue
                t, m2, ipr = (np.asarray(g[x], float) for x in ("t", "m2", "ipr"))
                keep = t > 0
                gamma = fits.get((kick, f0, chain))
                label = f"$F_0$ = {f0:g} N" + (rf" ($\gamma$ = {gamma:.2f})" if gamma is not None else "")
                axes[row][0].loglog(t[keep], m2[keep], color=f"C{k}")
                axes[row][1].loglog(t[keep], ipr[keep], color=f"C{k}", label=label)
                m2_curves.append((t[keep], m2[keep], f"C{k}"))
                inv_curves.append((t[keep], 1 / ipr[keep], f"C{k}"))
            guides(axes[row][0], m2_curves, (2, 1), fit)
            guides(axes[row][1], [(t, 1 / y, c) for t, y, c in inv_curves], (0, -1), fit)
            _inset_ld(axes[row][0], m2_curves, [0.09, 0.6, 0.33, 0.33], fit, ylim=(-0.5, 2.5))
            axes[row][0].set_ylabel(rf"{chain}: $\tilde m_2$ [beads$^2$]")
            axes[row][1].set_ylabel(rf"{chain}: $P^{{-1}}$")
            axes[row][1].legend(loc="lower left", fontsize=8)
            for ax in axes[row]:
                log_ticks(ax.xaxis)
                log_ticks(ax.yaxis)
        for ax in axes[-1]:
            ax.set_xlabel("time t [s]")
        fig.suptitle(f"{kick} kick: ensemble means (insets: log derivative $L_d$; shaded: the fit window)",
                     fontsize=11)
    return fig


def profiles(source, decades=15):
    """Averaged energy profiles <E_n(T)> along the chain on a log scale, one panel per kick and
    chain kind, one curve per F0. The axis shows `decades` decades below the largest energy (lower
    values are round-off, not physics). source: a granular.ExponentTable or the exponents prefix."""
    _, prof, _, _ = _exponent_data(source)
    if not prof:
        raise ValueError("no energy profiles in these results (profile_F0 was empty)")
    kicks = list(dict.fromkeys(k[0] for k in prof))
    chains = list(dict.fromkeys(k[2] for k in prof))
    top = max(np.max(v) for v in prof.values())
    with style():
        fig = figure(3.4 * len(chains) + 0.5, 3.0 * len(kicks) + 0.6)
        axes = fig.subplots(len(kicks), len(chains), squeeze=False, sharey=True, sharex=True)
        f0s = sorted({k[1] for k in prof}, reverse=True)
        for i, kick in enumerate(kicks):
            for j, chain in enumerate(chains):
                ax = axes[i][j]
                for k, f0 in enumerate(f0s):
                    energy = prof.get((kick, f0, chain))
                    if energy is None:
                        continue
                    energy = np.asarray(energy, float)
                    sites = np.arange(1, len(energy) + 1)
                    shown = np.where(energy > 0, energy, np.nan)
                    ax.semilogy(sites, shown, lw=0.8, color=f"C{k}", label=f"$F_0$ = {f0:g} N")
                ax.set_title(f"{chain}, {kick} kick", fontsize=11)
                ax.set_ylim(top * 10.0 ** (-decades), top * 3)
                log_ticks(ax.yaxis)
                if i == len(kicks) - 1:
                    ax.set_xlabel("bead n")
            axes[i][0].set_ylabel(r"$\langle E_n(T)\rangle$ [J]")
        axes[0][0].legend(fontsize=8)
    return fig


def _table_columns(source, suffix, key):
    """Columns of PREFIX<suffix>.csv (a path prefix) or of result[key] (an ExponentTable)."""
    if _io.is_path(source):
        path = os.fspath(source) + suffix
        if not os.path.exists(path):
            raise ValueError(f"{path}: not found" + (" (run exponents with --compare-paper)" if key == "paper" else ""))
        return _io.read_csv(path)
    if key not in source:
        raise ValueError(f"no {key!r} in these results" + (" (pass compare_paper=True)" if key == "paper" else ""))
    return source[key]


def _truthy(value):
    return value is True or value == "true" or (not isinstance(value, str) and bool(value))


def centres(source, chain="A"):
    """m~2(t) about the kicked site and about the energy centroid, side by side, for one chain kind,
    every kick (rows) and F0 (columns), with both fitted gamma: where the two definitions part
    (the paper writes its kick at n_c, the site; its F0 = 0.01-0.1 N values sit between the two).
    source: a granular.ExponentTable or the exponents tool's prefix."""
    groups, _, _, _ = _exponent_data(source)
    table = _table_columns(source, ".csv", "table")
    keys = [k for k in groups if k[2] == chain]
    if not keys:
        raise ValueError(f"no chain {chain!r} in these results (chains: {sorted({k[2] for k in groups})})")
    if "m2_centroid" not in groups[keys[0]]:
        raise ValueError("these results carry no m2 about the centroid")
    kicks = list(dict.fromkeys(k[0] for k in keys))
    f0s = list(dict.fromkeys(k[1] for k in keys))
    gamma = {}
    for i in range(len(table["gamma"])):
        if table["disorder"][i] == chain:
            site_first = table["centre"][i] == "site"
            pair = (table["gamma"][i], table["gamma_other"][i])
            gamma[(table["ic"][i], float(table["F0"][i]))] = pair if site_first else pair[::-1]
    fit = (4e-3, 10e-3)
    with style():
        fig = figure(3.0 * len(f0s) + 0.6, 2.9 * len(kicks) + 0.5)
        axes = fig.subplots(len(kicks), len(f0s), squeeze=False, sharex=True)
        for i, kick in enumerate(kicks):
            for j, f0 in enumerate(f0s):
                ax = axes[i][j]
                g = groups.get((kick, f0, chain))
                if g is None:
                    ax.set_visible(False)
                    continue
                t, site, centroid = (np.asarray(g[x], float) for x in ("t", "m2", "m2_centroid"))
                keep = t > 0
                ax.axvspan(*fit, color="0.92", zorder=0)
                ax.loglog(t[keep], site[keep], color="C0", label="about the kicked site")
                ax.loglog(t[keep], centroid[keep], "--", color="C3", label="about the centroid")
                if (kick, f0) in gamma:
                    gs, gc = gamma[(kick, f0)]
                    ax.text(0.04, 0.96, f"$\\gamma$: site {gs:.3f}\ncentroid {gc:.3f}", transform=ax.transAxes,
                            fontsize=8, va="top")
                ax.set_title(f"{kick}, $F_0$ = {f0:g} N", fontsize=10)
                log_ticks(ax.xaxis)
                log_ticks(ax.yaxis)
                if i == len(kicks) - 1:
                    ax.set_xlabel("time t [s]")
            axes[i][0].set_ylabel(rf"{chain}: $\tilde m_2$ [beads$^2$]")
        axes[0][0].legend(fontsize=7, loc="lower right")
        fig.suptitle(f"{chain}: second moment about the kicked site and about the energy centroid "
                     "(shaded: the fit window)", fontsize=11)
    return fig


def paper_comparison(source):
    """Our gamma about both centres beside the paper's Table I, one panel per kick; error bars are
    the sub-window spread and the realization bootstrap combined; * marks starred cells (the mean
    of L_d over the window, not a fitted slope). source: a granular.ExponentTable computed with
    compare_paper=True, the exponents prefix of a --compare-paper run, or its PREFIX-paper.csv."""
    if _io.is_path(source) and os.fspath(source).endswith(".csv"):
        rows = _io.read_csv(source)
    else:
        rows = _table_columns(source, "-paper.csv", "paper")
    kicks = list(dict.fromkeys(rows["ic"]))
    with style():
        fig = figure(12, 3.6 * len(kicks) + 0.4)
        axes = fig.subplots(len(kicks), 1, squeeze=False)[:, 0]
        for ax, kick in zip(axes, kicks):
            pick = [i for i, ic in enumerate(rows["ic"]) if ic == kick]
            x = np.arange(len(pick))
            ax.errorbar(x, [rows["paper_gamma"][i] for i in pick], yerr=[rows["paper_err"][i] for i in pick], fmt="ks",
                        ms=4, capsize=2, label="paper (Table I)")
            for centre, colour, dx in (("site", "C0", -0.2), ("centroid", "C3", 0.2)):
                value = np.array([rows[f"{centre}_gamma"][i] for i in pick], float)
                error = np.hypot([rows[f"{centre}_err"][i] for i in pick], [rows[f"{centre}_real_err"][i] for i in pick])
                ax.errorbar(x + dx, value, yerr=error, fmt="o", color=colour, ms=3.5, capsize=2,
                            label=rf"ours, $\tilde m_2$ about the {centre}")
                for k, i in enumerate(pick):
                    if _truthy(rows[f"{centre}_star"][i]):
                        ax.annotate("*", (x[k] + dx, value[k]), fontsize=10, color=colour, ha="center", va="bottom")
            ax.set_xticks(x)
            ax.set_xticklabels([f"{rows['disorder'][i]}\n{rows['F0'][i]:g} N" for i in pick], fontsize=8)
            ax.set_ylabel(r"exponent $\gamma$ ($\tilde m_2 \sim t^\gamma$)")
            ax.set_title(f"{kick} kick (error bars: sub-window spread and realization bootstrap combined; "
                         "* = mean $L_d$ on [4, 10] ms)", fontsize=10)
            ax.grid(axis="y", lw=0.3)
        axes[0].legend(fontsize=8, ncol=3)
    return fig


def spectral_densities(pairs, titles=None, fmax_khz=60):
    """g(nu) of the displacements (the paper's g) beside that of the velocities, one panel per
    run. A velocity kick leaves a permanent step in u_n(t), whose power ~ 1/nu^2 makes the
    displacement spectrum peak at 0 Hz; the velocity spectrum is flat under it and shows what
    vibrates. pairs: [(displacement, velocity), ...], each a SpreadingRun's spectral density
    (dict with freq_khz, g) or the CSV of spreading --spectrum / --spectrum-of velocity.
    fmax_khz: highest frequency shown [kHz]."""
    pairs = [tuple(p) for p in pairs]
    if not pairs or any(len(p) != 2 for p in pairs):
        raise ValueError("pairs: give (displacement spectrum, velocity spectrum) pairs")
    titles = list(titles) if titles else [os.fspath(u) if _io.is_path(u) else f"run {i + 1}" for i, (u, _) in
                                          enumerate(pairs)]
    with style():
        fig = figure(5.2 * len(pairs) + 0.4, 4.2)
        axes = fig.subplots(1, len(pairs), squeeze=False)[0]
        for ax, (u, v), title in zip(axes, pairs, titles):
            for source, label, colour in ((u, "of $u_n$ (the paper's $g$)", "C0"), (v, r"of $\dot u_n$", "C1")):
                d = _io.read_csv(source) if _io.is_path(source) else source
                ax.semilogy(d["freq_khz"], np.maximum(np.asarray(d["g"], float), 1e-14), lw=0.7, color=colour,
                            label=label)
            ax.set_xlim(0, fmax_khz)
            ax.set_ylim(1e-8, 2)
            ax.set_xlabel(r"frequency $\nu$ [kHz]")
            ax.set_ylabel(r"$g(\nu)$ (max 1)")
            ax.set_title(title, fontsize=10)
            ax.legend(fontsize=8)
    return fig


def cost(bench, time_unit=None):
    """Cost-accuracy curves of the integrators: max relative energy error and final-state error
    versus CPU time per realization, labelled by the time step. bench: the JSON file of
    dynamics_benchmark --benchmark_filter=CostAccuracy --benchmark_out=FILE (or its loaded dict)."""
    import json

    if _io.is_path(bench):
        with open(bench) as f:
            bench = json.load(f)
    runs = bench["benchmarks"]
    curves = {}
    for r in runs:
        if "max_energy_error" not in r:
            continue
        tau = r["name"].split("tau_ns:")[1].split("/")[0] if "tau_ns:" in r["name"] else "?"
        curves.setdefault(r.get("label", r["name"]), []).append(
            (r["cpu_time"], r["max_energy_error"], r.get("final_state_error", math.nan), tau))
    unit = time_unit or runs[0].get("time_unit", "ms")
    with style():
        fig = figure(11, 4.4)
        ax, bx = fig.subplots(1, 2)
        for i, (label, points) in enumerate(sorted(curves.items())):
            points.sort()
            t = [p[0] for p in points]
            ax.loglog(t, [p[1] for p in points], "o-", color=f"C{i}", label=label)
            bx.loglog(t, [p[2] for p in points], "o-", color=f"C{i}", label=label)
            for p in points:
                if p[3] != "?":
                    ax.annotate(f"{int(p[3]) / 1000:g}", (p[0], p[1]), fontsize=8, xytext=(3, 3),
                                textcoords="offset points")
        for axis in (ax, bx):
            axis.set_xlabel(f"CPU time per realization [{unit}]")
            log_ticks(axis.xaxis)
            log_ticks(axis.yaxis)
        ax.set_ylabel(r"max relative energy error $|H - H_0|/H_0$")
        bx.set_ylabel("final-state error (vs. reference)")
        ax.legend(title=r"labels: time step $\tau$ [µs]", title_fontsize=9)
    return fig
