#!/usr/bin/python3
"""Figures of the `spreading` tool's outputs, in the paper's layout.

usage:

  spreading_figures.py map      MAP.h5 [SPECTRUM.csv] -o map.png    energy map E_n(t) beside g(nu)
  spreading_figures.py forces   PREFIX-forces.csv [PREFIX-profile.csv] -o forces.png
  spreading_figures.py spread   A.csv [B.csv ...] [--labels a,b] -o spread.png    m2(t), P^-1(t)
  spreading_figures.py spectra  U.csv V.csv [U2.csv V2.csv ...] [--titles "a;b"] -o spectra.png
                                g(nu) of the displacements (the paper's) beside that of the velocities
  spreading_figures.py cost     BENCH.json -o cost.png    cost-accuracy of the schemes, from
                       dynamics_benchmark --benchmark_filter=CostAccuracy --benchmark_out=BENCH.json

A thin wrapper of `python3 -m granular.plot` (granular.plot.energy_map, forces, spreading,
spectral_densities, cost); `spreading_figures.py KIND --help` describes each.
"""
import sys

from _granular import plot_main

if __name__ == "__main__":
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        sys.exit(0 if len(sys.argv) > 1 else 2)
    kind = sys.argv[1]
    if kind not in ("map", "forces", "spread", "spectra", "cost"):
        print(f"spreading_figures.py: error: unknown figure {kind!r} (map, forces, spread, spectra, cost)", file=sys.stderr)
        sys.exit(2)
    sys.exit(plot_main([kind, *sys.argv[2:]], "spreading_figures.py"))
