#!/usr/bin/python3
"""Heat map of the mean mode IPR over (xi, mode number), one panel per q (the paper's IPR-map figure).

usage: /usr/bin/python3 tools/plot/ipr_map.py [ipr-map.csv] [-o ipr-map.png]
"""
import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"ipr_map.py: error: {path} has no rows")
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", nargs="?", default="ipr-map.csv")
    parser.add_argument("-o", "--output", help="PNG to write (default: the CSV name with .png)")
    args = parser.parse_args()
    out = args.output or os.path.splitext(args.csv)[0] + ".png"
    rows = load(args.csv)
    disorder = rows[0]["disorder"]
    qs = sorted({float(r["q"]) for r in rows})
    xis = sorted({float(r["xi"]) for r in rows})
    n = max(int(r["mode"]) for r in rows)
    maps = {q: np.full((n, len(xis)), np.nan) for q in qs}
    col = {xi: i for i, xi in enumerate(xis)}
    for r in rows:
        maps[float(r["q"])][int(r["mode"]) - 1, col[float(r["xi"])]] = float(r["ipr"])
    meta = {}
    json_path = os.path.splitext(args.csv)[0] + ".json"
    if os.path.exists(json_path):
        with open(json_path) as f:
            meta = json.load(f).get("parameters", {})

    vmax = max(np.nanmax(m) for m in maps.values())
    fig, axes = plt.subplots(1, len(qs), figsize=(4.2 * len(qs), 4.0), sharey=True, squeeze=False)
    step = xis[1] - xis[0] if len(xis) > 1 else 0.01
    extent = [xis[0] - step / 2, xis[-1] + step / 2, 0.5, n + 0.5]
    for ax, q in zip(axes[0], qs):
        im = ax.imshow(maps[q], origin="lower", aspect="auto", extent=extent, cmap="viridis", vmin=0, vmax=vmax,
                       interpolation="nearest")
        ax.set_title(f"{disorder}, q = {q:g}")
        ax.set_xlabel(r"size ratio $\xi = R_2/R_1$")
    axes[0][0].set_ylabel("mode number (increasing frequency)")
    fig.colorbar(im, ax=axes[0].tolist(), label=r"mean IPR $P^{-1}$")
    if meta:
        fig.suptitle(f"N = {meta.get('N')}, F0 = {meta.get('F0_N')} N, {meta.get('realizations')} realizations, "
                     f"seed {meta.get('seed')}", fontsize=9)
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
