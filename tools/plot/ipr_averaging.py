#!/usr/bin/python3
"""The two averagings of ipr-map in one figure: the ensemble's IPR against frequency, averaged by
mode number (each mode's mean frequency and mean IPR over realizations: points) and in frequency
bins (`ipr-map --bin-khz W`: the mean IPR of every mode of every realization in the bin: steps),
for one (q, xi) cell, with the number of modes per bin below. Mode-number means put points inside
band gaps, where no chain has a mode; the bins do not.

usage: /usr/bin/python3 tools/plot/ipr_averaging.py MODE.csv BINNED.csv [--q 0.5] [--xi 0.5]
       [--gap FB1,FB2] [-o docs/figures/ipr-averaging.png]
MODE.csv from `ipr-map` (columns disorder,q,xi,mode,freq_khz,ipr), BINNED.csv from the same command
with --bin-khz (disorder,q,xi,freq_lo_khz,freq_hi_khz,modes,ipr). --gap shades a band gap [kHz].
A thin wrapper of `python3 -m granular.plot ipr-averaging` (granular.plot.ipr_averaging).
"""
import argparse
import sys

from _granular import plot_main


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("mode_csv")
    p.add_argument("binned_csv")
    p.add_argument("--q", type=float, default=0.5)
    p.add_argument("--xi", type=float, default=0.5)
    p.add_argument("--gap", help="FB1,FB2: a band gap to shade [kHz]")
    p.add_argument("-o", "--output", default="ipr-averaging.png")
    a = p.parse_args(argv)
    return plot_main(["ipr-averaging", a.mode_csv, a.binned_csv, "--q", repr(a.q), "--xi", repr(a.xi), "-o", a.output,
                      "--dpi", "150", *(["--gap", a.gap] if a.gap else [])], "ipr_averaging.py")


if __name__ == "__main__":
    sys.exit(main())
