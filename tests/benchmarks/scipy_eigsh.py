#!/usr/bin/python3
"""SciPy's answer on the very same matrix, for the side-by-side benchmark.

usage: scipy_eigsh.py PREFIX KHZ K [OURS.csv]
PREFIX.diag.f64 / PREFIX.offdiag.f64 are written by `spectrum --dump-matrix PREFIX`.
Times eigsh(D, k=K, sigma=(2π·KHZ·1e3)², which='LM') — ARPACK shift-invert with a SuperLU
factorization of D − σI — and prints one line of JSON. With OURS.csv it also checks that the
frequencies agree (same K nearest in ω², which for these targets equals the K nearest in f).
Run with /usr/bin/python3 (Debian's, which has numpy and scipy).
"""
import json
import math
import sys
import time

import numpy as np
import scipy
import scipy.sparse as sp
from scipy.sparse.linalg import eigsh


def main(prefix, khz, k, ours=None):
    k = int(k)
    diag = np.fromfile(prefix + ".diag.f64", dtype="<f8")
    off = np.fromfile(prefix + ".offdiag.f64", dtype="<f8")
    a = sp.diags([off, diag, off], [-1, 0, 1], format="csc")
    sigma = (2 * math.pi * float(khz) * 1e3) ** 2
    t0 = time.perf_counter()
    values, vectors = eigsh(a, k=k, sigma=sigma, which="LM")
    seconds = time.perf_counter() - t0
    freq = np.sort(np.sqrt(np.maximum(values, 0)) / (2 * math.pi) * 1e-3)
    out = {"N": int(diag.size), "k": k, "seconds": seconds, "scipy": scipy.__version__,
           "matrix_bytes_csc": int(a.data.nbytes + a.indices.nbytes + a.indptr.nbytes)}
    if ours:
        theirs = np.loadtxt(ours, delimiter=",", skiprows=1, usecols=1, ndmin=1)
        theirs = np.sort(theirs)
        out["max_rel_freq_diff_vs_ours"] = float(np.max(np.abs(theirs - freq) / freq)) if theirs.size == freq.size else None
    print(json.dumps(out))


if __name__ == "__main__":
    main(*sys.argv[1:])
