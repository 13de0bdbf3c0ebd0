#!/usr/bin/env python3
"""Compare two partial-spectrum CSVs (mode,freq_khz,ipr): same modes, frequencies to 5e-11
relative (eigenvalues ω² to 1e-10), IPRs to 1e-8 relative for modes whose ω² is separated from
both listed neighbours by >= 1e-5 of its own value (closer modes may mix: any basis of a
near-degenerate cluster is valid). Standard library only. Exit 1 with a message on mismatch."""
import csv
import sys


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [(int(r["mode"]), float(r["freq_khz"]), float(r["ipr"])) for r in rows]


def main(a_path, b_path, min_rows):
    a, b = load(a_path), load(b_path)
    if len(a) < int(min_rows):
        sys.exit(f"{a_path}: {len(a)} rows, expected at least {min_rows}")
    if [r[0] for r in a] != [r[0] for r in b]:
        sys.exit(f"mode numbers differ: {[r[0] for r in a]} vs {[r[0] for r in b]}")
    compared = 0
    for j, ((m, fa, pa), (_, fb, pb)) in enumerate(zip(a, b)):
        if abs(fa - fb) > 5e-11 * fa:
            sys.exit(f"mode {m}: freq {fa!r} vs {fb!r}")
        w2 = fa * fa
        gaps = [abs(w2 - a[k][1] ** 2) for k in (j - 1, j + 1) if 0 <= k < len(a)]
        if 0 < j < len(a) - 1 and min(gaps) >= 1e-5 * w2:
            compared += 1
            if abs(pa - pb) > 1e-8 * pa:
                sys.exit(f"mode {m}: ipr {pa!r} vs {pb!r}")
    if compared == 0:
        sys.exit("no separated mode to compare IPRs on")
    print(f"{len(a)} modes agree; {compared} IPRs compared")


if __name__ == "__main__":
    main(*sys.argv[1:4])
