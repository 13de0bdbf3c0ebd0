"""Figures of the nonlinear dynamics after a kick: one run's energy map and forces, the spreading
m2(t) and P^-1(t) of runs or ensembles, spectral densities, and the integrators' cost."""
import json
import math
import os

import matplotlib
import numpy as np

from . import _io
from ._style import (chain_title, figure, guides, inset_log_derivative, log_thinned, log_ticks, mark_edges, style,
                     wrapped_suptitle)


def _chain_edges(meta):
    chain = meta.get("parameters", {}).get("chain", {})
    if chain.get("F0_N") and "xi" in chain:
        return _io.band_edges_khz(chain["xi"], chain["F0_N"], chain.get("R1_m")), chain
    return None, chain


def energy_map(source, spectral_density=None, t_window=None, site_window=None, floor=-12.0, band_edges=True,
               metadata=None):
    """Spatiotemporal energy map log10(E_n / sum E) over bead n and time, beside the spectral
    density g(nu) of the same run with the chain's band edges.

    source: a granular.SpreadingRun made with energy_map=True (and spectral_density=True), or the
    spreading tool's HDF5 energy map. spectral_density: the tool's spectrum CSV (a run carries its
    own). t_window: (t0, t1) [s] and site_window: (n0, n1) [beads, from 1] zoom in. floor: the
    lowest log10 relative energy shown (zeros beyond the front are blank). metadata: the run's JSON
    (a dict or its path) for the title and the band edges; for a map file, by default the JSON in
    its folder whose command line names it.
    """
    meta = {}
    if _io.is_path(source):
        t, site, energy = _io.read_hdf5_map(source)
        if metadata is None:
            meta = _io.run_json_naming(source)
    else:
        if source.energy_map is None:
            raise ValueError("this run has no energy map: run granular.spreading(..., energy_map=True)")
        t, site, energy = source.energy_map["t"], source.energy_map["site"], source.energy_map["energy"]
        meta = source.metadata
        if spectral_density is None and source.spectral_density is not None:
            spectral_density = source.spectral_density
    if _io.is_path(metadata):
        with open(metadata) as f:
            metadata = json.load(f)
    if metadata is not None:
        meta = metadata
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
            bx.xaxis.set_major_locator(matplotlib.ticker.LogLocator(base=10, numticks=4))  # a narrow panel
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


def _spread_curves(source, m2="m2"):
    """(t, m2 or m2_centroid, ipr, metadata) of a run or ensemble, or of the spreading tool's CSV."""
    if _io.is_path(source):
        d = _io.read_csv(source)
        meta = _io.read_json_beside(source)
        return d["t"], d[m2], d["ipr"], meta
    return source["t"], source[m2], source["ipr"], source["metadata"]


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
    fit = next((_io.fit_window(m["parameters"]) for _, _, _, m in data if m.get("parameters")), None)
    with style():
        fig = figure(11, 4.6)
        ax, bx = fig.subplots(1, 2)
        m2_curves, ipr_curves = [], []
        for i, ((t, m2, ipr, _), label) in enumerate(zip(data, labels)):
            t, m2, ipr = map(np.asarray, (t, m2, ipr))
            keep = t > 0
            drawn = log_thinned(t)
            ax.loglog(t[drawn], m2[drawn], color=f"C{i}", label=label)
            bx.loglog(t[drawn], ipr[drawn], color=f"C{i}", label=label)
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
        inset_log_derivative(ax, m2_curves, [0.09, 0.6, 0.36, 0.33], fit, ylim=(-0.5, 2.5))
        bx.legend(loc="lower left")
        # What the curves share (one run: its whole chain; several: what the legend does not tell).
        first = data[0][3].get("parameters", {}).get("chain", {})
        shared = {k: v for k, v in first.items()
                  if len(data) == 1 or k not in ("disorder", "q", "seed", "realization", "quasiperiodic")}
        title = chain_title(shared)
        wrapped_suptitle(fig, "energy spreading" + (f": {title}" if title else ""))
    return fig


def _lyapunov_data(source):
    """(t, exponents (times x k), gali (times x (k-1)), sali or None, metadata) of a run or of PREFIX-lyapunov.csv."""
    if _io.is_path(source):
        d = _io.read_csv(source)
        lambdas = sorted((c for c in d if c.startswith("lambda_")), key=lambda c: int(c.split("_")[1]))
        galis = sorted((c for c in d if c.startswith("gali_")), key=lambda c: int(c.split("_")[1]))
        if not lambdas:
            raise ValueError(f"{source}: no lambda_ columns (a spreading --lyapunov-vectors CSV?)")
        t = np.asarray(d["t"])
        exponents = np.column_stack([d[c] for c in lambdas])
        gali = np.column_stack([d[c] for c in galis]) if galis else np.empty((len(t), 0))
        beside = os.fspath(source)[:-len("-lyapunov.csv")] + ".json"
        if os.fspath(source).endswith("-lyapunov.csv") and os.path.exists(beside):
            with open(beside) as f:
                return t, exponents, gali, d.get("sali"), json.load(f)
        return t, exponents, gali, d.get("sali"), {}
    if source.lyapunov is None:
        raise ValueError("this run has no Lyapunov spectrum: run granular.spreading(..., mle=True, lyapunov_vectors=k)")
    lyap = source.lyapunov
    return lyap["t"], lyap["exponents"], lyap["gali"], lyap["sali"], source.metadata


def lyapunov(source):
    """The finite-time Lyapunov exponents lambda_1(t) .. lambda_k(t) beside the alignment indices
    GALI_2(t) .. GALI_k(t) and SALI(t), both on log axes.

    source: a granular.SpreadingRun made with mle=True, lyapunov_vectors=k, or the spreading tool's
    PREFIX-lyapunov.csv. Negative exponents are drawn as |lambda| dashed; zeros (t = 0, or an
    index that underflowed) are left out. GALI_k of a chaotic orbit falls as
    exp(-sum_j (lambda_1 - lambda_j) t); of a regular one it stays of order 1 for k <= N.
    """
    t, exponents, gali, sali, meta = _lyapunov_data(source)
    t, exponents, gali = np.asarray(t, float), np.asarray(exponents, float), np.asarray(gali, float)
    keep = t > 0
    _, chain = _chain_edges(meta)
    k = exponents.shape[1]
    with style():
        fig = figure(11, 4.6)
        ax, bx = fig.subplots(1, 2)
        for j in range(k):
            colour = matplotlib.cm.viridis(j / max(k - 1, 1))
            lam = exponents[keep, j]
            label = rf"$\lambda_{{{j + 1}}}$" if k <= 8 or j in (0, k - 1) else None
            positive = np.where(lam > 0, lam, np.nan)
            negative = np.where(lam < 0, -lam, np.nan)
            ax.loglog(t[keep], positive, color=colour, lw=1.0, label=label)
            if np.isfinite(negative).any():
                ax.loglog(t[keep], negative, color=colour, lw=1.0, ls="--")
        ax.set_xlabel("time t [s]")
        ax.set_ylabel(r"finite-time exponent $|\lambda_i(t)|$ [1/s] (dashed: < 0)")
        ax.legend(loc="lower left", fontsize=8, ncol=2)
        for j in range(gali.shape[1]):
            values = np.where(gali[keep, j] > 0, gali[keep, j], np.nan)
            colour = matplotlib.cm.plasma(j / max(gali.shape[1], 1))
            label = f"GALI$_{{{j + 2}}}$" if gali.shape[1] <= 8 or j in (0, gali.shape[1] - 1) else None
            bx.loglog(t[keep], values, color=colour, lw=1.0, label=label)
        if sali is not None:
            values = np.asarray(sali, float)[keep]
            bx.loglog(t[keep], np.where(values > 0, values, np.nan), color="0.2", lw=1.0, ls=":", label="SALI")
        if gali.shape[1] or sali is not None:
            bx.set_ylabel("alignment index")
            bx.legend(loc="lower left", fontsize=8, ncol=2)
            bx.set_xlabel("time t [s]")
        else:
            bx.set_visible(False)  # k = 1: no index
        for axis in (ax, bx):
            log_ticks(axis.xaxis)
        title = chain_title(chain)
        wrapped_suptitle(fig, f"Lyapunov spectrum, k = {k}" + (f": {title}" if title else ""))
    return fig


def _covariant_data(source):
    """The CLVs of a run or of PREFIX-clv.h5 as a dict (t, vectors samples x k x 2N, growth_rates, participation,
    centre) and the run's metadata (the JSON beside the file, if any)."""
    if _io.is_path(source):
        import h5py  # only for files

        with h5py.File(source, "r") as f:
            d = {name: np.array(f[name]) for name in ("t", "vectors", "growth_rates", "participation", "centre")}
        k = len(d["growth_rates"])
        d["vectors"] = d["vectors"].reshape(len(d["t"]), k, -1)
        beside = os.fspath(source)[:-len("-clv.h5")] + ".json"
        meta = {}
        if os.fspath(source).endswith("-clv.h5") and os.path.exists(beside):
            with open(beside) as f:
                meta = json.load(f)
        return d, meta
    if source.covariant is None:
        raise ValueError("this run has no covariant vectors: run granular.spreading(..., mle=True, "
                         "covariant_vectors=k)")
    return source.covariant, source.metadata


def covariant(source, sample=-1, floor=-8.0):
    """Where each covariant Lyapunov vector lives: its share of |w|^2 = |du|^2 + (t_unit dv)^2 on each bead at one
    sample (CLV index x bead, log colour) beside each CLV's participation number [beads] against its growth rate
    [1/s], coloured by its centre [bead].

    source: a granular.SpreadingRun made with mle=True, covariant_vectors=k, or the spreading tool's PREFIX-clv.h5
    (the JSON beside it titles the figure). sample: index into the CLVs' samples (default the last, t = T).
    floor: the lowest log10 share shown.
    """
    d, meta = _covariant_data(source)
    w = np.asarray(d["vectors"], float)[sample]  # k x 2N
    k, n = w.shape[0], w.shape[1] // 2
    t_unit = meta.get("covariant_vectors", {}).get("time_unit_s") or \
        meta.get("parameters", {}).get("lyapunov", {}).get("norm_time_unit_s", 1e-6)  # (0.2.0's key)
    share = w[:, :n] ** 2 + (t_unit * w[:, n:]) ** 2
    share /= share.sum(axis=1, keepdims=True)
    t = float(np.asarray(d["t"])[sample])
    growth = np.asarray(d["growth_rates"], float)
    participation = np.asarray(d["participation"], float)[sample]
    centre = np.asarray(d["centre"], float)[sample]
    _, chain = _chain_edges(meta)
    with style():
        fig = figure(11, 4.6)
        ax, bx = fig.subplots(1, 2)
        image = ax.imshow(np.log10(np.maximum(share, 10.0**floor)), aspect="auto", origin="lower", cmap="magma",
                          vmin=floor, vmax=0, extent=(0.5, n + 0.5, 0.5, k + 0.5), interpolation="nearest")
        fig.colorbar(image, ax=ax, label=r"$\log_{10}$ share of $\|w\|^2$ on the bead")
        ax.set_xlabel("bead n (from 1)")
        ax.set_ylabel("CLV index i (by exponent, largest first)")
        ax.set_title(f"t = {t:.4g} s", fontsize=10)
        points = bx.scatter(growth, participation, c=centre + 1, cmap="viridis", vmin=1, vmax=n, s=30)
        fig.colorbar(points, ax=bx, label="centre (bead, from 1)")
        bx.axvline(0, color="0.6", lw=0.8, ls=":")
        bx.set_xlabel(r"growth rate $\gamma_i$ [1/s] over the window")
        bx.set_ylabel("participation [beads]")
        bx.set_ylim(0, n + 0.5)
        title = chain_title(chain)
        wrapped_suptitle(fig, f"covariant Lyapunov vectors, k = {k}" + (f": {title}" if title else ""))
    return fig


def _start_label(meta):
    """How a spreading run started, from its metadata: the linear mode or the single-site kick."""
    parameters = meta.get("parameters", {})
    mode = parameters.get("mode_used")
    if mode:
        return f"mode {mode['mode']} ({mode['freq_khz']:.2f} kHz, IPR {mode['ipr']:.3g})"
    return f"single-site {parameters.get('ic', '')} kick"


def mode_kicks(runs, labels=None):
    """Energy spreading from linear modes against a single-site kick of the same energy: the second
    moment m~2 about the energy centroid [beads^2] (a mode's energy is not centred on one bead) and
    the participation P^-1 of the energy against time t [ms] on log-log axes, one curve per run.

    runs: granular.SpreadingRun results or spreading CSVs (JSON beside), e.g. of spreading --ic mode
    --mode K --energy E and of spreading --ic velocity. labels: one per run (default, from each
    run's metadata: the mode's number, frequency [kHz] and IPR, or 'single-site <ic> kick')."""
    if not isinstance(runs, (list, tuple)):
        runs = [runs]
    # matplotlib's default look (not style()), as docs/figures/mode-kicks.png was drawn
    fig = figure(10, 4.2)
    left, right = fig.subplots(1, 2)
    for i, source in enumerate(runs):
        t, m2, ipr, meta = _spread_curves(source, "m2_centroid")
        label = labels[i] if labels else _start_label(meta)
        left.loglog(np.asarray(t) * 1e3, m2, label=label)
        right.loglog(np.asarray(t) * 1e3, ipr, label=label)
    left.set_xlabel("t [ms]")
    left.set_ylabel("m2 about the energy centroid [bead$^2$]")
    right.set_xlabel("t [ms]")
    right.set_ylabel("P$^{-1}$ of the energy")
    left.legend(fontsize=7)
    fig.suptitle("Energy spreading from linear modes vs a single-site kick of the same energy")
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
