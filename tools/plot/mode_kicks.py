#!/usr/bin/python3
"""Spreading from linear modes against a single-site kick of the same energy: the second moment
m2 (about the energy centroid) and the participation P^-1 of the energy against time, one curve
per spreading run (`spreading --ic mode ...` and `spreading --ic velocity ...` CSVs).

usage: /usr/bin/python3 tools/plot/mode_kicks.py RUN.csv [RUN.csv ...] [-o docs/figures/mode-kicks.png]
Each run is labelled from its JSON: the mode number, frequency and IPR, or "single-site kick".
A thin wrapper of `python3 -m granular.plot mode-kicks` (granular.plot.mode_kicks).
"""
import argparse
import sys

from _granular import plot_main


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("-o", "--output", default="mode-kicks.png")
    a = p.parse_args(argv)
    return plot_main(["mode-kicks", *a.runs, "-o", a.output, "--dpi", "150"], "mode_kicks.py")


if __name__ == "__main__":
    sys.exit(main())
