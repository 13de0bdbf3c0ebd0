#!/usr/bin/python3
"""The peer a user would write: transfer-matrix Lyapunov exponents and node counts of a bead chain
in NumPy, vectorized over frequencies (one array operation per bead for all frequencies).

  localization_numpy.py --types chain.types --xi 0.5 --F0 10 --f 0.05:50:0.05 --output numpy.csv
  localization_numpy.py --write-types chain.types --N 10000000 --q 0.5 --seed 1   (an Anderson chain)

The chain physics (steel beads and flat steel walls, Hertz contacts, B = 1.5 A^(2/3) F0^(1/3)) is
written out here from the formulas, as a user would, not taken from the toolkit.
"""
import argparse
import time

import numpy as np

E, NU, RHO, R1 = 193e9, 0.3, 8027.17, 4.76e-3


def stiffness(r_a, r_b, f0):
    """Linear stiffness of the Hertz bond between radii r_a and r_b (np.inf: a flat wall)."""
    with np.errstate(invalid="ignore"):  # inf/inf at the walls, replaced by np.where
        r_eff = np.where(np.isinf(r_a), r_b, np.where(np.isinf(r_b), r_a, r_a * r_b / (r_a + r_b)))
    a = 2 * E / (3 * (1 - NU**2)) * np.sqrt(r_eff)
    return 1.5 * a ** (2 / 3) * f0 ** (1 / 3)


def chain(types, xi, f0):
    radius = np.where(types == 1, R1, xi * R1)
    mass = RHO * 4 / 3 * np.pi * radius**3
    padded = np.concatenate(([np.inf], radius, [np.inf]))
    return mass, stiffness(padded[:-1], padded[1:], f0)


def lyapunov(mass, b, freq_khz):
    """lambda = (1/N) ln ||(u_{N+1}, u_N)|| from u_0 = 0, u_1 = 1, and the sign changes of u."""
    w2 = (2 * np.pi * 1e3 * freq_khz) ** 2
    u_prev, u = np.zeros_like(w2), np.ones_like(w2)
    log_sum = np.zeros_like(w2)
    nodes = np.zeros(w2.shape, dtype=np.int64)
    n = len(mass)
    for i in range(n):
        u_next = ((b[i] + b[i + 1] - mass[i] * w2) * u - b[i] * u_prev) / b[i + 1]
        nodes += np.signbit(u_next) != np.signbit(u)
        u_prev, u = u, u_next
        if i % 8 == 7:  # renormalize before anything overflows
            scale = np.maximum(np.abs(u), np.abs(u_prev))
            log_sum += np.log(scale)
            u, u_prev = u / scale, u_prev / scale
    return (log_sum + 0.5 * np.log(u * u + u_prev * u_prev)) / n, nodes


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--types", help="bead types file (1 or 2 per line)")
    p.add_argument("--xi", type=float, default=0.5)
    p.add_argument("--F0", type=float, default=10.0)
    p.add_argument("--f", default="0.05:50:0.05", help="start:stop:step [kHz]")
    p.add_argument("--output", default="numpy.csv")
    p.add_argument("--write-types", help="write an Anderson chain's types to this file and stop")
    p.add_argument("--N", type=int, default=10_000_000)
    p.add_argument("--q", type=float, default=0.5)
    p.add_argument("--seed", type=int, default=1)
    args = p.parse_args()
    if args.write_types:
        rng = np.random.default_rng(args.seed)
        types = np.where(rng.random(args.N) < args.q, 1, 2)
        np.savetxt(args.write_types, types, fmt="%d")
        return
    start, stop, step = (float(x) for x in args.f.split(":"))
    freq = np.round(np.arange(start, stop + step / 2, step), 12)
    types = np.loadtxt(args.types, dtype=np.int64, comments="#")
    mass, b = chain(types, args.xi, args.F0)
    t0 = time.perf_counter()
    lam, nodes = lyapunov(mass, b, freq)
    elapsed = time.perf_counter() - t0
    with open(args.output, "w") as out:
        out.write("freq_khz,lyapunov,idos\n")
        for f, l, c in zip(freq, lam, nodes):
            out.write(f"{f!r},{l!r},{c / len(mass)!r}\n")
    print(f"numpy: {len(freq)} frequencies x {len(mass)} beads: transfer-matrix loop {elapsed:.2f} s")


if __name__ == "__main__":
    main()
