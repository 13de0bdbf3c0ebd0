#!/usr/bin/python3
"""Localization length of the infinite chain beside the IPR of finite chains of the same disorder.

Left: l(f) = 1/lambda from `localization` (transfer matrices) on a log scale, with its
statistical error and the band edges f1, f2, fb1, fb2, fb3 marked. Right: the IPR of every mode
of finite chains of the same disorder against frequency (the paper's Fig. 3 kind), from the
`spectrum` tool — run here for --realizations chains of --finite-N beads, or read from CSV files
given with --spectrum. A mode is extended in a finite chain where l(f) exceeds its length.

usage: /usr/bin/python3 tools/plot/localization.py loc.csv [-o loc.png]
           [--spectrum-tool build/spectrum --finite-N 1000 --realizations 5 | --spectrum a.csv b.csv]
The figure is granular.plot.localization.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from _granular import plot_main

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_TOOL = os.path.normpath(os.path.join(HERE, "..", "..", "build", "spectrum"))


def run_spectrum(tool, chain, n, realizations, folder):
    """Runs `spectrum` on the chains `localization` described; returns the CSV paths."""
    base = [tool, "--F0", str(chain["F0_N"])]
    if "R1_m" in chain:
        base += ["--R1", str(chain["R1_m"]), "--xi", str(chain["xi"])]
    if "radii_file" in chain:
        runs = [base + ["--radii", chain["radii_file"]]]
    elif "config_file" in chain:
        runs = [base + ["--config", chain["config_file"]]]
    else:
        base += ["--disorder", chain["disorder"], "--q", str(chain["q"]), "--N", str(n), "--seed", str(chain["seed"])]
        runs = [base + ["--realization", str(r)] for r in range(realizations)]
    paths = []
    for i, command in enumerate(runs):
        path = os.path.join(folder, f"spectrum-{i}.csv")
        subprocess.run(command + ["--output", path], check=True, stdout=subprocess.DEVNULL)
        paths.append(path)
    return paths


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog="\n".join(__doc__.splitlines()[1:]))
    parser.add_argument("csv", nargs="?", default="localization.csv", help="the localization tool's CSV")
    parser.add_argument("-o", "--output", help="figure file (default: the CSV's name with .png)")
    parser.add_argument("--spectrum", nargs="+", metavar="CSV", help="spectrum CSVs (mode,freq_khz,ipr) to plot")
    parser.add_argument("--spectrum-tool", default=DEFAULT_TOOL, help="the spectrum executable (default: %(default)s)")
    parser.add_argument("--finite-N", type=int, default=1000, help="beads of the finite chains (default: %(default)s)")
    parser.add_argument("--realizations", type=int, default=5, help="finite chains to diagonalize (default: %(default)s)")
    args = parser.parse_args()
    out = args.output or os.path.splitext(args.csv)[0] + ".png"
    meta_path = os.path.splitext(args.csv)[0] + ".json"
    chain = json.load(open(meta_path)).get("chain", {}) if os.path.exists(meta_path) else {}
    with tempfile.TemporaryDirectory() as folder:
        spectra, finite_n = args.spectrum or [], None
        if not spectra and chain and os.path.exists(args.spectrum_tool):
            spectra = run_spectrum(args.spectrum_tool, chain, args.finite_N, args.realizations, folder)
            finite_n = args.finite_N if "disorder" in chain else None
        elif not spectra:
            print(f"note: no spectrum CSVs and no {args.spectrum_tool}: plotting l(f) alone", file=sys.stderr)
        argv = ["localization", args.csv, "-o", out]
        if spectra:
            argv += ["--spectrum", *spectra]
        if finite_n:
            argv += ["--finite-N", str(finite_n)]
        return plot_main(argv, "localization.py")


if __name__ == "__main__":
    sys.exit(main())
