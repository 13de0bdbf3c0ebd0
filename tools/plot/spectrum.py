#!/usr/bin/python3
"""One chain's spectrum: frequency versus mode number, the IPR beside it, band edges dashed
(the paper's linear-spectrum figure).

usage: /usr/bin/python3 tools/plot/spectrum.py [spectrum.csv] [-o spectrum.png]
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
    parser.add_argument("csv", nargs="?", default="spectrum.csv")
    parser.add_argument("-o", "--output")
    args = parser.parse_args()
    out = args.output or os.path.splitext(args.csv)[0] + ".png"
    with open(args.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    mode = [int(r["mode"]) for r in rows]
    freq = [float(r["freq_khz"]) for r in rows]
    ipr = [float(r["ipr"]) for r in rows]
    meta = {}
    json_path = os.path.splitext(args.csv)[0] + ".json"
    if os.path.exists(json_path):
        with open(json_path) as f:
            meta = json.load(f)

    fig, (left, right) = plt.subplots(1, 2, figsize=(8, 4), sharey=True, gridspec_kw={"width_ratios": [3, 2]})
    left.plot(mode, freq, ".", ms=3)
    left.set_xlabel("mode number")
    left.set_ylabel("frequency f [kHz]")
    right.plot(ipr, freq, ".", ms=3, color="C3")
    right.set_xlabel(r"IPR $P^{-1}$")
    right.set_xscale("log")
    for name, value in meta.get("band_edges_khz", {}).items():
        for ax in (left, right):
            ax.axhline(value, ls="--", lw=0.8, color="0.4")
        right.annotate(name, (1, value), xycoords=("axes fraction", "data"), fontsize=8, ha="left", va="center")
    chain = meta.get("chain", {})
    if chain:
        fig.suptitle(", ".join(f"{k} = {chain[k]}" for k in ("disorder", "N", "xi", "q", "F0_N", "seed", "realization")
                               if k in chain), fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
