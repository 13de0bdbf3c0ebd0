#!/usr/bin/python3
"""A breather branch: energy against frequency with stability marked and the linear modes drawn,
three profiles as insets, one point's Floquet multipliers on the unit circle (docs/breathers.md).

usage: /usr/bin/python3 tools/plot/breathers.py [breathers.csv] [--point J] [-o breathers.png]
A thin wrapper of `python3 -m granular.plot breathers` (granular.plot.breather_branch).
"""
import sys

from _granular import plot_main

if __name__ == "__main__":
    sys.exit(plot_main(["breathers", *sys.argv[1:]], "breathers.py"))
