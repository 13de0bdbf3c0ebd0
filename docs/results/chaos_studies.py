"""The chaos studies of docs/chaos.md ("Studies"), from the Python package.

1. The paper's comparison, measured: the granular chain under the paper's protocol (2501 beads, Anderson
   disorder, a displacement kick at the centre, to 10 ms; 20 realizations) with the finite-time mLE Lambda(t),
   beside the disordered Klein-Gordon chain in weak chaos (W = 4, E = 0.4 on one site, 512 sites, to t = 1e5;
   8 realizations): the growth of m2 and the decay of Lambda, as slopes per decade.
2. How many orbits are chaotic against the precompression F0: 16-bead Anderson chains kicked at the centre
   bead at 0.05 m/s, 16 realizations per F0, to T = 0.1 s; an orbit counts as chaotic when GALI_2(T) < 1e-8
   (a regular orbit's GALI_2 stays of order one; a chaotic one's falls as exp(-(lambda_1 - lambda_2) t)).
3. Where the chaos lives: the covariant Lyapunov vectors of two of those orbits (every one of the 2N = 32), their
   participation against their growth rate.

Run from the repository's root after building:
    PYTHONPATH=build/python /usr/bin/python3 docs/results/chaos_studies.py
Writes docs/results/chaos-*.csv and docs/figures/chaos-*.png; prints the tables the page quotes.
"""
import csv
import pathlib
import sys
import time
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import granular as gr  # noqa: E402

root = pathlib.Path(__file__).resolve().parents[2]
warnings.filterwarnings("ignore", message=".*reach a wall.*")  # the 16-bead chains are short on purpose
warnings.filterwarnings("ignore", message=".*reached the walls.*")


def slopes(t, y, decades):
    """Least-squares slope of log10 y against log10 t within each [a, b) of `decades` (pairs of times)."""
    out = []
    for a, b in decades:
        keep = (t >= a) & (t <= b) & (y > 0)
        out.append(np.polyfit(np.log10(t[keep]), np.log10(y[keep]), 1)[0] if keep.sum() >= 3 else np.nan)
    return out


def write(name, rows):
    with (root / "docs/results" / name).open("w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


# 1. granular (paper's protocol) beside DKG (weak chaos)
start = time.time()
granular = {F0: gr.transport(F0=F0, realizations=20, mle=True, samples=100, threads=2) for F0 in (10.0, 0.1)}
dkg = gr.klein_gordon(N=512, W=4.0, energy=0.4, T=1e5, samples=60, realizations=8, threads=2)
print(f"part 1: {time.time() - start:.0f} s", file=sys.stderr)
rows = []
g_decades = [(1e-5, 1e-4), (1e-4, 1e-3), (1e-3, 1e-2)]
d_decades = [(1e2, 1e3), (1e3, 1e4), (1e4, 1e5)]
for F0, r in granular.items():
    m2, mle = slopes(r.t, r.m2, g_decades), slopes(r.t, r.mle, g_decades)
    for (a, b), s_m2, s_mle in zip(g_decades, m2, mle):
        rows.append({"chain": f"granular F0 = {F0:g} N", "t_from": a, "t_to": b, "m2_slope": s_m2, "mle_slope": s_mle,
                     "mle_at_end": float(np.interp(b, r.t, r.mle))})
d_m2, d_mle = slopes(dkg.t, dkg.m2, d_decades), slopes(dkg.t, 10 ** dkg.mean_log10_mle, d_decades)
for (a, b), s_m2, s_mle in zip(d_decades, d_m2, d_mle):
    rows.append({"chain": "DKG W = 4, E = 0.4", "t_from": a, "t_to": b, "m2_slope": s_m2, "mle_slope": s_mle,
                 "mle_at_end": float(np.interp(b, dkg.t, 10 ** dkg.mean_log10_mle))})
write("chaos-granular-vs-dkg.csv", rows)
for row in rows:
    print("  ".join(f"{k}={v:.3g}" if isinstance(v, float) else f"{k}={v}" for k, v in row.items()))

fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 3.8))
for F0, r in granular.items():
    a1.loglog(r.t / 1e-6, r.m2, label=f"granular, F0 = {F0:g} N (t in µs)")
    a2.loglog(r.t / 1e-6, r.mle * 1e-6, label=f"granular, F0 = {F0:g} N (Λ in 1/µs)")
a1.loglog(dkg.t, dkg.m2, "k", label="DKG W = 4 (t in 1/ω0)")
a2.loglog(dkg.t, 10 ** dkg.mean_log10_mle, "k", label="DKG W = 4 (Λ in ω0)")
for ax, what in ((a1, "m2 [sites²]"), (a2, "finite-time mLE Λ")):
    ax.set_xlabel("t (each chain's time unit)")
    ax.set_ylabel(what)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, frameon=False)
fig.suptitle("Spreading and chaos: granular chains (paper's protocol, 20 realizations) beside DKG (8)")
fig.tight_layout()
fig.savefig(root / "docs/figures/chaos-granular-vs-dkg.png", dpi=100)

# 2. the fraction of chaotic orbits against F0
start = time.time()
rows = []
for F0 in (0.01, 0.1, 1.0, 3.0, 10.0):
    for realization in range(16):
        chain = gr.anderson(N=16, F0=F0, realization=realization)
        run = gr.spreading(chain, ic="velocity", beta=0.05, T=0.1, dt=1e-7, fit=(0.02, 0.1), mle=True,
                           lyapunov_vectors=2)
        gali2 = float(run.lyapunov["gali"][-1][0])
        rows.append({"F0_N": F0, "realization": realization, "lambda_1_per_s": float(run.lyapunov["exponents"][-1][0]),
                     "gali_2": gali2, "chaotic": int(gali2 < 1e-8)})
print(f"part 2: {time.time() - start:.0f} s", file=sys.stderr)
write("chaos-fraction.csv", rows)
for F0 in sorted({r["F0_N"] for r in rows}):
    sel = [r for r in rows if r["F0_N"] == F0]
    lam = np.array([r["lambda_1_per_s"] for r in sel])
    print(f"F0 = {F0:g} N: {sum(r['chaotic'] for r in sel)}/{len(sel)} chaotic; lambda_1(T) median {np.median(lam):.0f}"
          f"/s, range {lam.min():.0f} .. {lam.max():.0f}/s; GALI_2(T) median {np.median([r['gali_2'] for r in sel]):.2g}")

# 3. CLVs of a chaotic orbit at F0 = 0.01 N and 1 N: participation against growth rate
start = time.time()
fig, ax = plt.subplots(figsize=(5.5, 3.8))
rows = []
for F0, marker in ((0.01, "o"), (1.0, "s")):
    run = gr.spreading(gr.anderson(N=16, F0=F0, realization=0), ic="velocity", beta=0.05, T=0.02, dt=1e-7,
                       fit=(0.01, 0.02), mle=True, covariant_vectors=32)
    c = run.covariant
    part = np.asarray(c["participation"]).mean(axis=0)  # over the samples
    centre = np.asarray(c["centre"]).mean(axis=0)
    ax.scatter(c["growth_rates"], part, marker=marker, label=f"F0 = {F0:g} N")
    for i, (g, p, x) in enumerate(zip(c["growth_rates"], part, centre)):
        rows.append({"F0_N": F0, "clv": i + 1, "growth_rate_per_s": float(g), "participation_beads": float(p),
                     "centre_bead": float(x)})
print(f"part 3: {time.time() - start:.0f} s", file=sys.stderr)
write("chaos-clv-localization.csv", rows)
ax.set_xlabel("CLV growth rate [1/s]")
ax.set_ylabel("participation [beads] (mean over samples)")
ax.set_title("CLVs of a 16-bead chain (2N = 32), T = 20 ms", fontsize=10)
ax.legend(frameon=False)
ax.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(root / "docs/figures/chaos-clv-participation.png", dpi=100)
for F0 in (0.01, 1.0):
    sel = [r for r in rows if r["F0_N"] == F0]
    g = np.array([r["growth_rate_per_s"] for r in sel])
    p = np.array([r["participation_beads"] for r in sel])
    fast = np.abs(g) >= np.sort(np.abs(g))[-8]
    print(f"F0 = {F0:g} N: participation of the 8 fastest-growing/shrinking CLVs {p[fast].mean():.2f}, "
          f"of the 8 nearest zero {p[np.argsort(np.abs(g))[:8]].mean():.2f} beads (of 16)")
