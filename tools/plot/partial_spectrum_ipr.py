#!/usr/bin/python3
"""IPR versus frequency of the K modes nearest a frequency, for growing chain length N (issue 3).

Runs `spectrum --near` once per N on the same disorder and
seed, then plots IPR (log) against f − f0, one colour per N. Extended modes have IPR ~ 1/N and
drop as N grows; localized ones keep an N-independent IPR.

usage: /usr/bin/python3 tools/plot/partial_spectrum_ipr.py --tool build/spectrum
           [--disorder A] [--xi 0.5] [--q 0.5] [--near 15] [--count 40]
           [--sizes 1000,10000,100000,1000000] [--method bisect] [-o partial-spectrum-ipr.png]
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def run(tool, n, args, folder):
    out = os.path.join(folder, f"n{n}.csv")
    cmd = [tool, "--disorder", args.disorder, "--xi", str(args.xi), "--q", str(args.q), "--N", str(n),
           "--near", str(args.near), "--count", str(args.count), "--method", args.method, "--seed", str(args.seed),
           "--quiet", "--output", out]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"partial_spectrum_ipr.py: {' '.join(cmd)} failed: {done.stderr.strip()}")
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))
    return [float(r["freq_khz"]) for r in rows], [float(r["ipr"]) for r in rows]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--tool", default="build/spectrum")
    p.add_argument("--disorder", default="A")
    p.add_argument("--xi", type=float, default=0.5)
    p.add_argument("--q", type=float, default=0.5)
    p.add_argument("--near", type=float, default=15.0, help="target frequency [kHz]")
    p.add_argument("--count", type=int, default=40)
    p.add_argument("--sizes", default="1000,10000,100000,1000000")
    p.add_argument("--method", default="bisect")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("-o", "--output", default="partial-spectrum-ipr.png")
    args = p.parse_args()
    sizes = [int(float(s)) for s in args.sizes.split(",")]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    with tempfile.TemporaryDirectory() as folder:
        for n, colour in zip(sizes, plt.cm.viridis([i / max(1, len(sizes) - 1) for i in range(len(sizes))])):
            f, ipr = run(args.tool, n, args, folder)
            ax.semilogy([x - args.near for x in f], ipr, "o", ms=4, color=colour, label=f"N = {n:g}")
            ax.axhline(1.5 / n, color=colour, lw=0.6, ls=":")  # a plane wave with fixed ends: 3/(2N)
    # the K nearest span ~K/N of the band: a symmetric log axis keeps every N readable
    ax.set_xscale("symlog", linthresh=1e-5)
    ax.set_xlabel(f"f − {args.near:g} kHz [kHz] (symmetric log)")
    ax.set_ylabel("mode IPR  Σv⁴/(Σv²)²")
    ax.set_title(f"{args.disorder}, ξ = {args.xi:g}, q = {args.q:g}: {args.count} modes nearest {args.near:g} kHz "
                 f"(dotted: 3/(2N))", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=150)
    print(args.output)


if __name__ == "__main__":
    main()
