#!/usr/bin/python3
"""Ensemble-mean correlation rho(d) versus distance with its spread and the infinite-chain theory.

usage: /usr/bin/python3 tools/plot/correlations.py [correlations.csv ...] [-o correlations.png]
"""
import argparse
import csv
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", nargs="*", default=["correlations.csv"])
    parser.add_argument("-o", "--output")
    args = parser.parse_args()
    out = args.output or os.path.splitext(args.csv[0])[0] + ".png"
    fig, ax = plt.subplots(figsize=(6, 4))
    for i, path in enumerate(args.csv):
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        d = [int(r["distance"]) for r in rows]
        label = path
        json_path = os.path.splitext(path)[0] + ".json"
        if os.path.exists(json_path):
            with open(json_path) as f:
                p = json.load(f)["parameters"]
            label = f"{p['disorder']}, q = {p['q']}"
        ax.errorbar(d, [float(r["rho_mean"]) for r in rows], yerr=[float(r["rho_std"]) for r in rows], fmt="o",
                    ms=4, capsize=2, color=f"C{i}", label=f"{label} (mean ± std)")
        ax.plot(d, [float(r["rho_theory"]) for r in rows], "-", color=f"C{i}", lw=1, label=f"{label} theory")
    ax.axhline(0, color="0.6", lw=0.5)
    ax.set_xlabel("distance d [beads]")
    ax.set_ylabel(r"correlation $\rho(d)$")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
