#!/usr/bin/python3
"""Localization length of the infinite chain beside the IPR of finite chains of the same disorder.

Left: l(f) = 1/lambda from `localization` (transfer matrices) on a log scale, with its
statistical error and the band edges f1, f2, fb1, fb2, fb3 marked. Right: the IPR of every mode
of finite chains of the same disorder against frequency (the paper's Fig. 3 kind), from the
`spectrum` tool — run here for --realizations chains of --finite-N beads, or read from CSV files
given with --spectrum. A mode is extended in a finite chain where l(f) exceeds its length.

usage: /usr/bin/python3 tools/plot/localization.py loc.csv [-o loc.png]
           [--spectrum-tool build/spectrum --finite-N 1000 --realizations 5 | --spectrum a.csv b.csv]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_TOOL = os.path.normpath(os.path.join(HERE, "..", "..", "build", "spectrum"))


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


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

    rows = read_rows(args.csv)
    meta_path = os.path.splitext(args.csv)[0] + ".json"
    meta = json.load(open(meta_path)) if os.path.exists(meta_path) else {}
    chain = meta.get("chain", {})
    f = [float(r["freq_khz"]) for r in rows]
    lam = [float(r["lyapunov"]) for r in rows]
    err = [float(r["lyapunov_err"]) for r in rows]
    ell = [1 / x if x > 0 else math.nan for x in lam]
    ell_lo = [1 / (x + e) if x > 0 else math.nan for x, e in zip(lam, err)]
    ell_hi = [1 / (x - e) if x > e else math.nan for x, e in zip(lam, err)]

    spectra, finite_n = args.spectrum or [], None
    with tempfile.TemporaryDirectory() as folder:
        if not spectra and chain and os.path.exists(args.spectrum_tool):
            spectra = run_spectrum(args.spectrum_tool, chain, args.finite_N, args.realizations, folder)
            finite_n = args.finite_N if "disorder" in chain else None
        elif not spectra:
            print(f"note: no spectrum CSVs and no {args.spectrum_tool}: plotting l(f) alone", file=sys.stderr)
        modes = [(float(r["freq_khz"]), float(r["ipr"])) for path in spectra for r in read_rows(path)]
        if finite_n is None and spectra:
            finite_n = len(read_rows(spectra[0]))

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2), sharex=True)
    left.fill_between(f, ell_lo, ell_hi, color="C0", alpha=0.3, lw=0, label="± statistical error")
    left.plot(f, ell, color="C0", lw=1, label=r"$\ell = 1/\lambda$ (transfer matrix)")
    left.set_yscale("log")
    left.set_xlabel("frequency f [kHz]")
    left.set_ylabel(r"localization length $\ell$ [beads]")
    if finite_n:
        left.axhline(finite_n, ls=":", color="0.3", lw=1)
        left.annotate(f"N = {finite_n} (right)", (0.01, finite_n), xycoords=("axes fraction", "data"),
                      fontsize=8, va="bottom")
    if modes:
        right.plot([m[0] for m in modes], [m[1] for m in modes], ".", ms=2, color="C3")
    right.set_yscale("log")
    right.set_xlabel("frequency f [kHz]")
    right.set_ylabel(r"mode IPR $P^{-1}$")
    right.set_title(f"modes of {len(spectra)} finite chain(s)" + (f" of {finite_n} beads" if finite_n else ""),
                    fontsize=9)
    for name, value in meta.get("band_edges_khz", {}).items():
        for ax in (left, right):
            ax.axvline(value, ls="--", lw=0.8, color="0.5")
        left.annotate(name, (value, 1.0), xycoords=("data", "axes fraction"), fontsize=8, ha="center", va="bottom")
    left.legend(fontsize=8, loc="lower left")
    keys = ("disorder", "xi", "q", "F0_N", "seed", "realization", "N", "config_file", "radii_file")
    fig.suptitle(", ".join(f"{k} = {chain[k]}" for k in keys if k in chain), fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
