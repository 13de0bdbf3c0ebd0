#!/usr/bin/python3
"""The paper's transport figures from an `exponents` run:
PREFIX-spreading-<kick>.png (m2 and P^-1 per chain kind and F0, guide slopes, L_d insets),
PREFIX-profiles.png (averaged energy profiles E_n(T)), PREFIX-centres.png (m2 about the kicked
site beside m2 about the centroid, chain A) and, after --compare-paper, PREFIX-paper.png (our
gamma about both centres beside the paper's Table I).

usage: /usr/bin/python3 tools/plot/exponents.py [PREFIX]      (default PREFIX: exponents)
A thin wrapper of `python3 -m granular.plot exponents PREFIX --all` (granular.plot.exponents,
profiles, centres, paper_comparison).
"""
import sys

from _granular import plot_main

if __name__ == "__main__":
    sys.exit(plot_main(["exponents", *sys.argv[1:], "--all"], "exponents.py"))
