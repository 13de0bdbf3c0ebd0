"""Figures of the paper's transport study (an exponents run, granular.ExponentTable): m2(t) and
P^-1(t) per chain kind and F0, the two centres of m2, the energy profiles, the fitted exponents
beside the paper's Table I."""
import os

import numpy as np

from . import _io
from ._style import figure, guides, inset_log_derivative, log_thinned, log_ticks, style, wrapped_suptitle


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


def _fit_window(meta):
    """(start, stop) [s] of the fit window, from a run's metadata (a run's parameters or each case of a
    table carry their own; None where no case was fitted)."""
    for case in [meta.get("parameters", {})] + meta.get("cases", []):
        if _io.fit_window(case):
            return _io.fit_window(case)
    return None


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
    fit = _fit_window(meta)
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
                drawn = log_thinned(t)
                axes[row][0].loglog(t[drawn], m2[drawn], color=f"C{k}")
                axes[row][1].loglog(t[drawn], ipr[drawn], color=f"C{k}", label=label)
                m2_curves.append((t[keep], m2[keep], f"C{k}"))
                inv_curves.append((t[keep], 1 / ipr[keep], f"C{k}"))
            guides(axes[row][0], m2_curves, (2, 1), fit)
            guides(axes[row][1], [(t, 1 / y, c) for t, y, c in inv_curves], (0, -1), fit)
            inset_log_derivative(axes[row][0], m2_curves, [0.09, 0.6, 0.33, 0.33], fit, ylim=(-0.5, 2.5))
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
    groups, _, _, meta = _exponent_data(source)
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
    fit = _fit_window(meta)
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
                if fit:
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
        wrapped_suptitle(fig, f"{chain}: second moment about the kicked site and about the energy centroid"
                         + ("\n(shaded: the fit window)" if fit else ""))
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


_CHAIN_ORDER = {"h": 0, "A": 1, "RDM1": 2, "RDM2": 3}


def _study(source):
    """The cases of an exponents run as {(ic, F0, disorder): its table row}, and the run's metadata,
    from a granular.ExponentTable, an exponents prefix or its PREFIX.csv (JSON beside)."""
    if _io.is_path(source):
        path = os.fspath(source)
        path = path if path.endswith(".csv") else path + ".csv"
        table, meta = _io.read_csv(path), _io.read_json_beside(path)
    else:
        table, meta = source["table"], source["metadata"]
    rows = [{name: column[i] for name, column in table.items()} for i in range(len(table["ic"]))]
    return {(r["ic"], float(r["F0"]), r["disorder"]): r for r in rows}, meta


def _study_label(meta, rows):
    """('10 ms', '10 ms (fit 4–10 ms, 500 real.)'): T and the fit window of an exponents run, from its
    metadata, and the realizations of its rows; (None, None) when the metadata does not say."""
    case = (meta.get("cases") or [{}])[0]
    T, fit = case.get("duration", case.get("T_s")), _fit_window(meta)
    if T is None or not fit:
        return None, None
    realizations = max(int(float(r["realizations"])) for r in rows)
    return f"{T * 1e3:g} ms", f"{T * 1e3:g} ms (fit {fit[0] * 1e3:g}–{fit[1] * 1e3:g} ms, {realizations} real.)"


def study_comparison(source, reference, labels=None):
    """The exponents of one exponents run beside those of a reference run (e.g. the long-time study
    at T = 100 ms beside the 10 ms study of record): gamma (m~2 ~ t^gamma) above, eta (P^-1 ~
    t^-eta) below, for every disordered case (kick, F0 [N], chain) both runs have; error bars the
    bootstrap over realizations, open markers the starred cells (not a power law: the mean L_d).

    source, reference: granular.ExponentTable results, exponents prefixes or their PREFIX.csv (with
    the JSON beside). labels: the legend entries (reference's, source's); default from each run's
    metadata, e.g. '10 ms (fit 4–10 ms, 500 real.)' (T, fit window, realizations per case)."""
    cases, meta = _study(source)
    reference_cases, reference_meta = _study(reference)
    keys = sorted((k for k in cases if k[2] != "h" and k in reference_cases),
                  key=lambda k: (k[0], -k[1], _CHAIN_ORDER.get(k[2], 9)))
    if not keys:
        raise ValueError("study_comparison: the two runs have no disordered case in common")
    runs = ([reference_cases[k] for k in keys], [cases[k] for k in keys])
    (t_ref, reference_label), (t_run, run_label) = _study_label(reference_meta, runs[0]), _study_label(meta, runs[1])
    labels = list(labels) if labels else [reference_label or "reference", run_label or "this run"]
    title = f"at {t_ref} and at {t_run}" if t_ref and t_run else "of two runs"
    # matplotlib's default look (not style()), as docs/figures/long-times-exponents.png was drawn
    fig = figure(11, 6.5)
    axes = fig.subplots(2, 1, sharex=True)
    for ax, name, label in ((axes[0], "gamma", r"$\gamma$ ($\tilde m_2 \propto t^\gamma$)"),
                            (axes[1], "eta", r"$\eta$ ($P^{-1} \propto t^{-\eta}$)")):
        for dx, rows, colour, when in ((-0.12, runs[0], "C0", labels[0]), (0.12, runs[1], "C3", labels[1])):
            for i, r in enumerate(rows):
                starred = _truthy(r[name + "_star"])
                ax.errorbar(i + dx, float(r[name]), yerr=float(r[name + "_real_err"]), fmt="o", ms=5, color=colour,
                            mfc="white" if starred else colour, capsize=2, label=when if i == 0 else None)
        ax.set_ylabel(label)
        ax.grid(axis="y", color="0.9")
    axes[0].legend(loc="lower right", fontsize=8, title="open: not a power law (*)", title_fontsize=8)
    axes[1].set_xticks(list(range(len(keys))))
    axes[1].set_xticklabels([f"{ic[:4]}. {f0:g} N {chain}" for ic, f0, chain in keys], rotation=70, fontsize=7)
    fig.suptitle(f"Transport exponents {title} (error bars: realization bootstrap)", fontsize=11)
    return fig
