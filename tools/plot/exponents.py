#!/usr/bin/python3
"""The paper's transport figures from an `exponents` run:
PREFIX-spreading-<kick>.png: m2(t) (about the kicked site) and P^-1(t) on log-log axes, one row per
chain kind, one curve per F0, guide slopes (2 and 1 for m2; 0 and -1 for P^-1), the log derivative
L_d (on consecutive samples, as the tool takes it) in an inset;
PREFIX-centres.png: m2 about the kicked site and about the energy centroid, side by side, for one
chain kind (A by default), both kicks and every F0: where the two definitions part;
PREFIX-profiles.png: the averaged energy profile E_n(T) on a log scale;
PREFIX-paper.png (when PREFIX-paper.csv exists, from --compare-paper): our gamma about both centres
beside the paper's Table I, with the combined error bars of the z-scores.

usage: /usr/bin/python3 tools/plot/exponents.py [PREFIX]      (default PREFIX: exponents)
"""
import csv
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def log_derivative(t, y):
    """L_d = d ln y / d ln t on consecutive samples, as the exponents tool computes it."""
    out_t, out_s = [], []
    for i in range(len(t) - 1):
        if t[i] > 0 and t[i + 1] > t[i] and y[i] > 0 and y[i + 1] > 0:
            out_t.append(math.sqrt(t[i] * t[i + 1]))
            out_s.append(math.log(y[i + 1] / y[i]) / math.log(t[i + 1] / t[i]))
    return out_t, out_s


def guide(ax, t, y0, slope, label):
    t0, t1 = t[len(t) // 3], t[-1]
    ax.plot([t0, t1], [y0, y0 * (t1 / t0) ** slope], "k--", lw=0.8)
    ax.annotate(label, (t1, y0 * (t1 / t0) ** slope), fontsize=7, ha="right", va="bottom")


def spreading_figure(curves, kick, prefix):
    rows = [r for r in curves if r["ic"] == kick]
    chains = list(dict.fromkeys(r["disorder"] for r in rows))
    f0s = list(dict.fromkeys(r["F0"] for r in rows))
    data = defaultdict(lambda: ([], [], []))
    for r in rows:
        t, m2, ipr = data[(r["disorder"], r["F0"])]
        t.append(float(r["t"]))
        m2.append(float(r["m2"]))
        ipr.append(float(r["ipr"]))
    fig, axes = plt.subplots(len(chains), 2, figsize=(9, 2.8 * len(chains)), squeeze=False)
    for row, chain in enumerate(chains):
        for col, (name, index) in enumerate([("m2", 1), ("P^{-1}", 2)]):
            ax = axes[row][col]
            inset = ax.inset_axes([0.62, 0.1 if col == 0 else 0.6, 0.35, 0.3])
            for k, f0 in enumerate(f0s):
                series = data[(chain, f0)]
                t = [x for x, y in zip(series[0], series[index]) if x > 0]
                y = [y for x, y in zip(series[0], series[index]) if x > 0]
                if not t:
                    continue
                ax.loglog(t, y, color=f"C{k}", lw=1.2, label=f"F0 = {f0} N")
                lt, ls = log_derivative(t, y)
                inset.semilogx(lt, ls, color=f"C{k}", lw=0.8)
            t = data[(chain, f0s[0])][0][1:]
            y_ref = data[(chain, f0s[0])][index][len(t) // 3 + 1]
            if col == 0:
                guide(ax, t, y_ref, 2, "slope 2")
                guide(ax, t, y_ref / 10, 1, "slope 1")
            else:
                guide(ax, t, y_ref, 0, "slope 0")
                guide(ax, t, y_ref, -1, "slope -1")
            if col == 1:  # P^-1 swings on the vibrations' time scale: its L_d on 10 µs steps is large
                inset.set_ylim(-3, 3)
            inset.set_title(r"$L_d$" + (" (clipped to ±3)" if col == 1 else ""), fontsize=7)
            inset.tick_params(labelsize=6)
            ax.set_ylabel(rf"${name}$ ({chain})")
            if row == len(chains) - 1:
                ax.set_xlabel("t [s]")
        axes[row][0].legend(fontsize=6, loc="upper left")
    fig.suptitle(f"{kick} kick: ensemble means", fontsize=10)
    fig.tight_layout()
    out = f"{prefix}-spreading-{kick}.png"
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def centres_figure(curves, table, prefix, chain="A"):
    rows = [r for r in curves if r["disorder"] == chain]
    if not rows:
        return
    kicks = list(dict.fromkeys(r["ic"] for r in rows))
    f0s = list(dict.fromkeys(r["F0"] for r in rows))
    gamma = {(r["ic"], r["F0"]): r for r in table if r["disorder"] == chain}
    fig, axes = plt.subplots(len(kicks), len(f0s), figsize=(2.9 * len(f0s), 2.7 * len(kicks)), squeeze=False)
    for i, kick in enumerate(kicks):
        for j, f0 in enumerate(f0s):
            ax = axes[i][j]
            pick = [r for r in rows if r["ic"] == kick and r["F0"] == f0 and float(r["t"]) > 0]
            t = [float(r["t"]) * 1e3 for r in pick]
            ax.loglog(t, [float(r["m2"]) for r in pick], "C0", lw=1.2, label="about the kicked site")
            ax.loglog(t, [float(r["m2_centroid"]) for r in pick], "C3--", lw=1.2, label="about the centroid")
            ax.axvspan(4, 10, color="0.92", zorder=0)
            g = gamma.get((kick, f0))
            if g:
                site, centroid = (g["gamma"], g["gamma_other"]) if g["centre"] == "site" else (g["gamma_other"], g["gamma"])
                ax.text(0.04, 0.96, f"$\\gamma$ site {float(site):.3f}\ncentroid {float(centroid):.3f}", transform=ax.transAxes,
                        fontsize=7, va="top")
            ax.set_title(f"{kick}, F0 = {f0} N", fontsize=8)
            ax.tick_params(labelsize=7)
            if i == len(kicks) - 1:
                ax.set_xlabel("t [ms]", fontsize=8)
            if j == 0:
                ax.set_ylabel(rf"$\tilde m_2$ ({chain}) [bead$^2$]", fontsize=8)
    axes[0][0].legend(fontsize=6, loc="lower right")
    fig.tight_layout()
    out = f"{prefix}-centres.png"
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def paper_figure(rows, prefix):
    kicks = list(dict.fromkeys(r["ic"] for r in rows))
    fig, axes = plt.subplots(len(kicks), 1, figsize=(11, 3.3 * len(kicks)), squeeze=False)
    for ax, kick in zip(axes[:, 0], kicks):
        pick = [r for r in rows if r["ic"] == kick]
        x = list(range(len(pick)))
        paper = [float(r["paper_gamma"]) for r in pick]
        ax.errorbar(x, paper, yerr=[float(r["paper_err"]) for r in pick], fmt="ks", ms=4, capsize=2, label="paper (Table I)")
        for centre, colour, dx in (("site", "C0", -0.2), ("centroid", "C3", 0.2)):
            value = [float(r[f"{centre}_gamma"]) for r in pick]
            error = [math.hypot(float(r[f"{centre}_err"]), float(r[f"{centre}_real_err"])) for r in pick]
            ax.errorbar([i + dx for i in x], value, yerr=error, fmt="o", color=colour, ms=3.5, capsize=2,
                        label=f"ours, m2 about the {centre}")
            for i, r in enumerate(pick):
                if r[f"{centre}_star"] == "true":
                    ax.annotate("*", (i + dx, value[i]), fontsize=9, color=colour, ha="center", va="bottom")
        ax.set_xticks(x)
        ax.set_xticklabels([f"{r['disorder']}\n{r['F0']} N" for r in pick], fontsize=7)
        ax.set_ylabel(r"$\gamma$")
        ax.set_title(f"{kick} kick (error bars: sub-window spread and realization bootstrap combined; * = mean L_d)",
                     fontsize=9)
        ax.grid(axis="y", lw=0.3)
    axes[0][0].legend(fontsize=7, ncol=3)
    fig.tight_layout()
    out = f"{prefix}-paper.png"
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def profile_figure(profiles, prefix):
    if not profiles:
        return
    groups = defaultdict(lambda: ([], []))
    for r in profiles:
        site, energy = groups[(r["ic"], r["disorder"], r["F0"])]
        site.append(int(r["site"]))
        energy.append(float(r["energy"]))
    kicks = list(dict.fromkeys(k[0] for k in groups))
    chains = list(dict.fromkeys(k[1] for k in groups))
    fig, axes = plt.subplots(len(kicks), len(chains), figsize=(3.2 * len(chains), 2.8 * len(kicks)), squeeze=False,
                             sharey=True)
    for i, kick in enumerate(kicks):
        for j, chain in enumerate(chains):
            ax = axes[i][j]
            for k, ((kk, cc, f0), (site, energy)) in enumerate(sorted(groups.items())):
                if kk == kick and cc == chain:
                    ax.semilogy(site, [max(e, 1e-300) for e in energy], lw=0.7, label=f"F0 = {f0} N")
            ax.set_title(f"{chain}, {kick}", fontsize=8)
            ax.set_xlabel("bead n")
            ax.set_ylim(bottom=1e-30)
    axes[0][0].set_ylabel(r"$\langle E_n(T)\rangle$ [J]")
    axes[0][0].legend(fontsize=6)
    fig.tight_layout()
    out = f"{prefix}-profiles.png"
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def main():
    prefix = sys.argv[1] if len(sys.argv) > 1 else "exponents"
    curves = read(f"{prefix}-curves.csv")
    for kick in dict.fromkeys(r["ic"] for r in curves):
        spreading_figure(curves, kick, prefix)
    centres_figure(curves, read(f"{prefix}.csv"), prefix)
    profile_figure(read(f"{prefix}-profiles.csv"), prefix)
    try:
        paper = read(f"{prefix}-paper.csv")
    except FileNotFoundError:
        paper = None
    if paper:
        paper_figure(paper, prefix)


if __name__ == "__main__":
    main()
