#!/usr/bin/python3
"""IPR versus frequency of the K modes nearest a frequency, for growing chain length N.

Runs `spectrum --near` once per N on the same disorder and
seed, then plots IPR (log) against f − f0, one colour per N. Extended modes have IPR ~ 1/N and
drop as N grows; localized ones keep an N-independent IPR.

usage: /usr/bin/python3 tools/plot/partial_spectrum_ipr.py --tool build/spectrum
           [--disorder A] [--xi 0.5] [--q 0.5] [--near 15] [--count 40]
           [--sizes 1000,10000,100000,1000000] [--method bisect] [-o partial-spectrum-ipr.png]
The figure is granular.plot.partial_spectrum_ipr.
"""
import argparse
import os
import subprocess
import sys
import tempfile

from _granular import plot_main


def run(tool, n, args, folder):
    out = os.path.join(folder, f"n{n}.csv")
    cmd = [tool, "--disorder", args.disorder, "--xi", str(args.xi), "--q", str(args.q), "--N", str(n),
           "--near", str(args.near), "--count", str(args.count), "--method", args.method, "--seed", str(args.seed),
           "--quiet", "--output", out]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"partial_spectrum_ipr.py: {' '.join(cmd)} failed: {done.stderr.strip()}")
    return out


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
    with tempfile.TemporaryDirectory() as folder:
        files = [run(args.tool, n, args, folder) for n in sizes]
        return plot_main(["partial-spectrum-ipr", *files, "--near", str(args.near), "-o", args.output],
                         "partial_spectrum_ipr.py")


if __name__ == "__main__":
    sys.exit(main())
