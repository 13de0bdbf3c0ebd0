#!/usr/bin/python3
"""The IPR map as a physicist would script it with NumPy/SciPy: the peer `ipr-map` is timed against.

Same job as `ipr-map` with its defaults (docs/physics.md, sections 1–3): Anderson disorder, xi = 0.1:1 step 0.01,
q = 0.2, 0.5, 0.8, N = 100, F0 = 10 N, 100 realizations, steel beads between flat steel walls.
Chains have the same sizes and disorder statistics as ipr-map's (NumPy's PCG64 instead of
Philox, so not the same chains). Each realization is one scipy.linalg.eigh_tridiagonal call
with eigenvectors (LAPACK dstemr underneath) on the dynamical matrix scaled to unit largest
entry, then P^-1 = sum v^4 / (sum v^2)^2 with v = M^{-1/2} w.

Raw SI matrices (entries ~1e10 1/s^2) make dstemr fail on 17.8 % of these chains (487 of
2730 sampled), so the matrix is scaled to unit largest entry; it still fails on ~0.5 % (15 of
the same 2730), and then the script falls back to the dense numpy.linalg.eigh instead of
returning garbage (the count is printed).

Usage: /usr/bin/python3 ipr_map_scipy.py [--realizations R] [--xi-step S] [--processes P] [--output FILE]
(use /usr/bin/python3: it has Debian's python3-numpy and python3-scipy). --processes 1 (the
default) is the plain loop a physicist writes; --processes 2 spreads the (q, xi) cells over a
multiprocessing pool, to compare with ipr-map on the same two cores.
"""
import argparse
import math
import multiprocessing
import sys
import time

import numpy as np
import scipy.linalg

E, NU, RHO = 193e9, 0.3, 8027.17  # steel
R1 = 4.76e-3


def hertz(reff):
    """Hertz coefficient of two same-material bodies with effective radius reff."""
    return 2 * E / (3 * (1 - NU * NU)) * np.sqrt(reff)


def chain_matrix(radii, f0):
    """Diagonal, off-diagonal of D = M^-1/2 K M^-1/2 and m^-1/2 for beads between flat walls."""
    mass = RHO * 4.0 / 3.0 * math.pi * radii**3
    a = np.empty(len(radii) + 1)
    a[0] = hertz(radii[0])  # flat wall: the effective radius is the sphere's
    a[-1] = hertz(radii[-1])
    a[1:-1] = hertz(radii[:-1] * radii[1:] / (radii[:-1] + radii[1:]))
    b = 1.5 * np.cbrt(a * a * f0)
    s = 1.0 / np.sqrt(mass)
    diag = (b[:-1] + b[1:]) * s * s
    off = -b[1:-1] * s[:-1] * s[1:]
    return diag, off, s


def solve(diag, off, s):
    """(omega^2, IPR, 1 if dstemr failed and the dense solver was used else 0)."""
    scale = max(np.abs(diag).max(), np.abs(off).max())
    fallback = 0
    try:
        w, v = scipy.linalg.eigh_tridiagonal(diag / scale, off / scale)
    except (np.linalg.LinAlgError, ValueError):
        dense = np.diag(diag / scale) + np.diag(off / scale, 1) + np.diag(off / scale, -1)
        w, v = np.linalg.eigh(dense)
        fallback = 1
    u = v * s[:, None]
    u2 = u * u
    ipr = (u2 * u2).sum(axis=0) / u2.sum(axis=0) ** 2
    return w * scale, ipr, fallback


def cell(args):
    """Mean frequency [kHz] and IPR of every mode over the realizations of one (q, xi)."""
    q, xi, types, f0 = args
    n = types.shape[1]
    freq = np.zeros(n)
    ipr = np.zeros(n)
    fallbacks = 0
    for t in types:
        radii = np.where(t, R1, xi * R1)
        w2, p_inv, fallback = solve(*chain_matrix(radii, f0))
        freq += np.sqrt(np.maximum(w2, 0)) / (2 * math.pi) * 1e-3
        ipr += p_inv
        fallbacks += fallback
    freq /= len(types)
    ipr /= len(types)
    return [(q, xi, k + 1, freq[k], ipr[k]) for k in range(n)], fallbacks


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--realizations", type=int, default=100)
    p.add_argument("--xi-step", type=float, default=0.01)
    p.add_argument("--N", type=int, default=100)
    p.add_argument("--F0", type=float, default=10.0)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--processes", type=int, default=1)
    p.add_argument("--output", default="ipr-map-scipy.csv")
    args = p.parse_args()
    n, f0 = args.N, args.F0
    xis = np.round(np.arange(0.1, 1.0 + 1e-9, args.xi_step), 10)
    rng = np.random.default_rng(args.seed)
    t0 = time.perf_counter()
    cells = []
    for q in (0.2, 0.5, 0.8):
        types = np.array([rng.random(n) < q for _ in range(args.realizations)])  # True: type 1
        cells.extend((q, xi, types, f0) for xi in xis)
    if args.processes > 1:
        with multiprocessing.Pool(args.processes) as pool:
            results = pool.map(cell, cells, chunksize=4)
    else:
        results = [cell(c) for c in cells]
    rows = [row for block, _ in results for row in block]
    fallbacks = sum(f for _, f in results)
    solves = len(cells) * args.realizations
    with open(args.output, "w") as f:
        f.write("disorder,q,xi,mode,freq_khz,ipr\n")
        for q, xi, k, fr, pi in rows:
            f.write(f"A,{q!r},{xi!r},{k},{fr!r},{pi!r}\n")
    dt = time.perf_counter() - t0
    print(f"ipr_map_scipy: {solves} solves in {dt:.3f} s ({dt / solves * 1e6:.1f} us per solve); "
          f"dstemr failed on {fallbacks} scaled chains (dense eigh used)", file=sys.stderr)


if __name__ == "__main__":
    main()
