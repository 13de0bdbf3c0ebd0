#!/usr/bin/python3
"""Spreading from linear modes against a single-site kick of the same energy: the second moment
m2 (about the energy centroid) and the participation P^-1 of the energy against time, one curve
per spreading run (`spreading --ic mode ...` and `spreading --ic velocity ...` CSVs).

usage: /usr/bin/python3 tools/plot/mode_kicks.py RUN.csv [RUN.csv ...] [-o docs/figures/mode-kicks.png]
Each run is labelled from its JSON: the mode number, frequency and IPR, or "single-site kick".
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


def label(path):
    meta_path = os.path.splitext(path)[0] + ".json"
    meta = json.load(open(meta_path)) if os.path.exists(meta_path) else {}
    mode = meta.get("parameters", {}).get("mode_used")
    if mode:
        return f"mode {mode['mode']} ({mode['freq_khz']:.2f} kHz, IPR {mode['ipr']:.3g})"
    return f"single-site {meta.get('parameters', {}).get('ic', '')} kick"


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("-o", "--output", default="mode-kicks.png")
    a = p.parse_args(argv)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    for path in a.runs:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        t = np.array([float(r["t"]) for r in rows]) * 1e3
        left.loglog(t, [float(r["m2_centroid"]) for r in rows], label=label(path))
        right.loglog(t, [float(r["ipr"]) for r in rows], label=label(path))
    left.set_xlabel("t [ms]")
    left.set_ylabel("m2 about the energy centroid [bead$^2$]")
    right.set_xlabel("t [ms]")
    right.set_ylabel("P$^{-1}$ of the energy")
    left.legend(fontsize=7)
    fig.suptitle("Energy spreading from linear modes vs a single-site kick of the same energy")
    fig.tight_layout()
    fig.savefig(a.output, dpi=150)
    return 0


if __name__ == "__main__":
    sys.exit(main())
