#!/usr/bin/python3
"""Heat map of the mean mode IPR over (xi, mode number), one panel per q (the paper's IPR-map figure).

usage: /usr/bin/python3 tools/plot/ipr_map.py [ipr-map.csv] [-o ipr-map.png] [--log-color]
A thin wrapper of `python3 -m granular.plot ipr-map` (granular.plot.ipr_map).
"""
import sys

from _granular import plot_main

if __name__ == "__main__":
    sys.exit(plot_main(["ipr-map", *sys.argv[1:]], "ipr_map.py"))
