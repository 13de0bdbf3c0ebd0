#!/usr/bin/python3
"""Log-log figure of the crystal scaling benchmark: solve time and peak memory against beads.

usage: crystal_scaling_plot.py SCALING.csv OUT.png
SCALING.csv is written by tests/benchmarks/crystal_scaling.sh (method,beads,wall_s,solve_s,peak_mb).
Each method's solve seconds (and SciPy's eigsh seconds) on the left, peak RSS on the right, with the
fitted power of N printed in the legend.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

LABELS = {"arpack": "ours: ARPACK + Eigen LDLᵀ, 1 process",
          "slepc": "ours: SLEPc + MUMPS LDLᵀ, 1 rank",
          "slepc2": "ours: SLEPc + MUMPS LDLᵀ, 2 ranks",
          "scipy": "SciPy eigsh (ARPACK + SuperLU)"}


def main(path, out):
    rows = np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8")
    fig, (ax_t, ax_m) = plt.subplots(1, 2, figsize=(10, 4.2))
    for method in dict.fromkeys(rows["method"]):
        r = rows[rows["method"] == method]
        n, t, m = r["beads"].astype(float), r["solve_s"].astype(float), r["peak_mb"].astype(float)
        power = f", N^{np.polyfit(np.log(n), np.log(t), 1)[0]:.2f}" if n.size > 1 else ""
        ax_t.loglog(n, t, "o-", label=LABELS.get(method, method) + power)
        ax_m.loglog(n, m, "o-", label=LABELS.get(method, method))
    ax_t.set(xlabel="beads N", ylabel="solve: 20 modes nearest the target [s]")
    ax_m.set(xlabel="beads N", ylabel="peak resident memory [MB]")
    for ax in (ax_t, ax_m):
        ax.grid(True, which="both", alpha=0.3)
    ax_t.legend(fontsize=7)
    fig.suptitle("Mass-disordered hexagonal crystal (w = 0.3, walls, F0 = 10 N): shift-invert modes")
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    main(*sys.argv[1:])
