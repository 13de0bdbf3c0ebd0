#!/usr/bin/python3
"""Ensemble-mean correlation rho(d) versus distance with its spread and the infinite-chain theory.

usage: /usr/bin/python3 tools/plot/correlations.py [correlations.csv ...] [--labels a,b] [-o correlations.png]
A thin wrapper of `python3 -m granular.plot correlations` (granular.plot.correlations).
"""
import sys

from _granular import plot_main

if __name__ == "__main__":
    sys.exit(plot_main(["correlations", *sys.argv[1:]], "correlations.py"))
