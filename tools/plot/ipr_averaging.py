#!/usr/bin/python3
"""The two averagings of ipr-map in one figure: the ensemble's IPR against frequency, averaged by
mode number (each mode's mean frequency and mean IPR over realizations: points) and in frequency
bins (`ipr-map --bin-khz W`: the mean IPR of every mode of every realization in the bin: steps),
for one (q, xi) cell, with the number of modes per bin below. Mode-number means put points inside
band gaps, where no chain has a mode; the bins do not.

usage: /usr/bin/python3 tools/plot/ipr_averaging.py MODE.csv BINNED.csv [--q 0.5] [--xi 0.5]
       [--gap FB1,FB2] [-o docs/figures/ipr-averaging.png]
MODE.csv from `ipr-map` (columns disorder,q,xi,mode,freq_khz,ipr), BINNED.csv from the same command
with --bin-khz (disorder,q,xi,freq_lo_khz,freq_hi_khz,modes,ipr). --gap shades a band gap [kHz].
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def rows(path, q, xi):
    with open(path, newline="") as f:
        out = [r for r in csv.DictReader(f) if abs(float(r["q"]) - q) < 1e-12 and abs(float(r["xi"]) - xi) < 1e-12]
    if not out:
        sys.exit(f"ipr_averaging.py: {path}: no rows with q = {q}, xi = {xi}")
    return out


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("mode_csv")
    p.add_argument("binned_csv")
    p.add_argument("--q", type=float, default=0.5)
    p.add_argument("--xi", type=float, default=0.5)
    p.add_argument("--gap", help="FB1,FB2: a band gap to shade [kHz]")
    p.add_argument("-o", "--output", default="ipr-averaging.png")
    a = p.parse_args(argv)
    by_mode = rows(a.mode_csv, a.q, a.xi)
    binned = rows(a.binned_csv, a.q, a.xi)
    if "mode" not in by_mode[0] or "freq_lo_khz" not in binned[0]:
        sys.exit("ipr_averaging.py: give the mode-averaged CSV first, the --bin-khz CSV second")
    f_mode = np.array([float(r["freq_khz"]) for r in by_mode])
    ipr_mode = np.array([float(r["ipr"]) for r in by_mode])
    lo = np.array([float(r["freq_lo_khz"]) for r in binned])
    hi = np.array([float(r["freq_hi_khz"]) for r in binned])
    count = np.array([float(r["modes"]) for r in binned])
    ipr_bin = np.array([float(r["ipr"]) for r in binned])
    disorder = by_mode[0]["disorder"]

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6.4, 5.6), sharex=True, height_ratios=[3, 1.3])
    edges = np.append(lo, hi[-1])
    top.stairs(np.where(count > 0, ipr_bin, np.nan), edges, color="tab:blue", lw=1.6,
               label=f"frequency bins of {hi[0] - lo[0]:g} kHz (every mode of every realization)")
    top.plot(f_mode, ipr_mode, "o", ms=3, color="tab:orange", label="by mode number (mean f, mean IPR)")
    bottom.stairs(count, edges, color="tab:blue", fill=True, alpha=0.5)
    if a.gap:
        g1, g2 = (float(x) for x in a.gap.split(","))
        for ax in (top, bottom):
            ax.axvspan(g1, g2, color="0.85", zorder=0, label="gap (fb1, fb2) of the diatomic chain" if ax is top else None)
    top.set_ylabel("IPR")
    top.set_title(f"{disorder}, q = {a.q:g}, ξ = {a.xi:g}: the two averagings of ipr-map")
    top.legend(fontsize=8, loc="upper left")
    bottom.set_ylabel("modes per bin")
    bottom.set_xlabel("frequency f [kHz]")
    fig.tight_layout()
    fig.savefig(a.output, dpi=150)
    return 0


if __name__ == "__main__":
    sys.exit(main())
