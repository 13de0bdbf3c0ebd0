#!/usr/bin/python3
"""The paper's transport figures from an `exponents` run:
PREFIX-spreading-<kick>.png: m2(t) and P^-1(t) on log-log axes, one row per chain kind, one curve
per F0, guide slopes (2 and 1 for m2; 0 and -1 for P^-1), the log derivative L_d in an inset;
PREFIX-profiles.png: the averaged energy profile E_n(T) on a log scale.

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


def log_derivative(t, y, step=0.1):
    """L_d over steps of at least 0.1 in ln t, as the exponents tool computes it."""
    out_t, out_s, j = [], [], 0
    for i in range(len(t)):
        j = max(j, i + 1)
        while j < len(t) and math.log(t[j] / t[i]) < step:
            j += 1
        if j == len(t):
            break
        if y[i] > 0 and y[j] > 0:
            out_t.append(math.sqrt(t[i] * t[j]))
            out_s.append(math.log(y[j] / y[i]) / math.log(t[j] / t[i]))
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
            inset.set_title(r"$L_d$", fontsize=7)
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
    profile_figure(read(f"{prefix}-profiles.csv"), prefix)


if __name__ == "__main__":
    main()
