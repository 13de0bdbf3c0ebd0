#!/usr/bin/python3
"""SciPy's answer on the very same crystal matrix, for the side-by-side benchmark of `crystal --near`.

usage: crystal_scipy.py PREFIX KHZ K [OURS.csv]
PREFIX.row_start.u64 / .column.u64 / .value.f64 are written by `crystal --dump-matrix PREFIX`. Times
eigsh(D, k=K, sigma=(2 pi KHZ 1e3)^2, which='LM') -- ARPACK shift-invert with SuperLU's factorization of
D - sigma I, what a SciPy user would write -- and prints one line of JSON. With OURS.csv (the tool's CSV) it
also reports the largest relative difference of the sorted frequencies. Run with /usr/bin/python3.
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
    indptr = np.fromfile(prefix + ".row_start.u64", dtype="<u8").astype(np.int64)
    indices = np.fromfile(prefix + ".column.u64", dtype="<u8").astype(np.int64)
    data = np.fromfile(prefix + ".value.f64", dtype="<f8")
    n = indptr.size - 1
    a = sp.csr_matrix((data, indices, indptr), shape=(n, n)).tocsc()
    sigma = (2 * math.pi * float(khz) * 1e3) ** 2
    t0 = time.perf_counter()
    values, _ = eigsh(a, k=k, sigma=sigma, which="LM")
    seconds = time.perf_counter() - t0
    freq = np.sort(np.sign(values) * np.sqrt(np.abs(values)) / (2 * math.pi) * 1e-3)
    out = {"rows": int(n), "k": k, "seconds": seconds, "scipy": scipy.__version__}
    if ours:
        theirs = np.sort(np.loadtxt(ours, delimiter=",", skiprows=1, usecols=1, ndmin=1))
        out["max_rel_freq_diff_vs_ours"] = (float(np.max(np.abs(theirs - freq) / np.abs(freq)))
                                            if theirs.size == freq.size else None)
    print(json.dumps(out))


if __name__ == "__main__":
    main(*sys.argv[1:])
