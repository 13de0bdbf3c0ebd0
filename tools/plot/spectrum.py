#!/usr/bin/python3
"""One chain's spectrum: frequency versus mode number, the IPR beside it, band edges dashed
(the paper's linear-spectrum figure).

usage: /usr/bin/python3 tools/plot/spectrum.py [spectrum.csv] [-o spectrum.png]
A thin wrapper of `python3 -m granular.plot spectrum` (granular.plot.spectrum).
"""
import sys

from _granular import plot_main

if __name__ == "__main__":
    sys.exit(plot_main(["spectrum", *sys.argv[1:]], "spectrum.py"))
