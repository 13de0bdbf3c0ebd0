"""Finite-size scaling of the 2D IPR map (docs/crystals.md, "Localization: finite-size scaling").

Mass-disordered hexagonal crystals with walls at three sizes L x L (N = L^2 beads): the mean vector
IPR of every mode in 2 kHz bins, times N. An extended mode spreads over the crystal, so its IPR.N
stays of order one as N grows; a mode localized on a patch of xi^2 beads keeps its IPR, so IPR.N
grows in proportion to N. The IPR length xi/d = sqrt(sqrt(3) / (4 pi IPR)) is what an exponential
envelope |v|^2 ~ exp(-2r/xi) on the hexagonal lattice (one bead per sqrt(3)/2 d^2) would give: a
scale, meaningful where IPR.N has stopped depending on N.

Run from the repository's root after building:
    PYTHONPATH=build/python /usr/bin/python3 docs/results/crystal_finite_size.py
Writes docs/results/crystal-finite-size.csv, docs/figures/crystal-finite-size.png and, for larger
crystals by their modes nearest 15 kHz, docs/results/crystal-finite-size-near.csv.
"""
import csv
import math
import pathlib
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import granular as gr  # noqa: E402

SIZES = {12: 32, 24: 8, 48: 2}  # L: realizations (about the same number of modes per size)
WIDTHS = [0.5, 0.9]
BIN_HZ = 2000.0
root = pathlib.Path(__file__).resolve().parents[2]
rows = []
for L, realizations in SIZES.items():
    start = time.time()
    m = gr.crystal_ipr_map(lattice="hexagonal", Lx=L, Ly=L, widths=WIDTHS, realizations=realizations, bin_hz=BIN_HZ,
                           seed=11, threads=2)
    print(f"L = {L}: {realizations} realizations in {time.time() - start:.0f} s", file=sys.stderr)
    n = L * L
    for w_index, w in enumerate(WIDTHS):
        for b in range(len(m.freq_lo_khz)):
            count = int(m.modes[w_index][b])
            if count == 0:
                continue
            ipr = float(m.ipr[w_index][b])
            rows.append({"L": L, "N": n, "width": w, "freq_lo_khz": m.freq_lo_khz[b], "freq_hi_khz": m.freq_hi_khz[b],
                         "modes": count, "ipr": ipr, "ipr_N": ipr * n,
                         "ipr_length_spacings": math.sqrt(math.sqrt(3) / (4 * math.pi * ipr))})

out = root / "docs/results/crystal-finite-size.csv"
with out.open("w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)

fig, axes = plt.subplots(1, len(WIDTHS), figsize=(5 * len(WIDTHS), 3.8), sharey=True)
for ax, w in zip(axes, WIDTHS):
    for L in SIZES:
        sel = [r for r in rows if r["L"] == L and r["width"] == w]
        f = np.array([(r["freq_lo_khz"] + r["freq_hi_khz"]) / 2 for r in sel])
        ax.semilogy(f, [r["ipr_N"] for r in sel], "o-", ms=3, label=f"{L} x {L} (N = {L * L})")
    ax.set_title(f"mass disorder w = {w}")
    ax.set_xlabel("frequency [kHz]")
    ax.grid(True, which="both", alpha=0.3)
axes[0].set_ylabel("mean IPR x N")
axes[0].legend()
fig.suptitle("Hexagonal crystals with walls, F0 = 10 N: extended where IPR.N does not grow with N")
fig.tight_layout()
fig.savefig(root / "docs/figures/crystal-finite-size.png", dpi=100)
print(f"wrote {out} and docs/figures/crystal-finite-size.png", file=sys.stderr)

# Beyond dense LAPACK: the modes nearest a frequency (crystal_ipr_map's near/count, ARPACK) of
# crystals up to 192 x 192, where the three sizes above leave xi undecided (12-18 kHz at w = 0.9).
NEAR_KHZ, NEAR_COUNT, NEAR_WIDTH = 15.0, 60, 0.9
NEAR_SIZES = {24: 16, 48: 8, 96: 8, 192: 4}  # L: realizations
near_rows = []
for L, realizations in NEAR_SIZES.items():
    start = time.time()
    m = gr.crystal_ipr_map(lattice="hexagonal", Lx=L, Ly=L, widths=[NEAR_WIDTH], realizations=realizations,
                           bin_hz=BIN_HZ, seed=11, near=NEAR_KHZ, count=NEAR_COUNT, threads=2)
    modes = m.modes[0]
    filled = modes > 0
    ipr = float(np.sum(m.ipr[0][filled] * modes[filled]) / np.sum(modes[filled]))  # over every mode
    n = L * L
    near_rows.append({"L": L, "N": n, "width": NEAR_WIDTH, "near_khz": NEAR_KHZ, "modes": int(modes.sum()),
                      "ipr": ipr, "ipr_N": ipr * n, "ipr_length_spacings": math.sqrt(math.sqrt(3) / (4 * math.pi * ipr))})
    print(f"L = {L}: {realizations} x {NEAR_COUNT} modes near {NEAR_KHZ} kHz in {time.time() - start:.0f} s, "
          f"IPR.N = {ipr * n:.1f}", file=sys.stderr)
near_out = root / "docs/results/crystal-finite-size-near.csv"
with near_out.open("w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(near_rows[0]))
    writer.writeheader()
    writer.writerows(near_rows)
print(f"wrote {near_out}", file=sys.stderr)
