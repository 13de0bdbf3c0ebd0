#!/usr/bin/python3
"""Figures of the `spreading` tool's outputs (issue 4), in the paper's layout.

Run with Debian's /usr/bin/python3 (python3-matplotlib, python3-h5py):

  spreading_figures.py map      MAP.h5 SPECTRUM.csv  -o map.png      energy map E_n(t) beside g(nu)
  spreading_figures.py forces   PREFIX-forces.csv PREFIX-profile.csv -o forces.png
                                                                     force vs t at each bead beside the force profile at T
  spreading_figures.py spread   A.csv [B.csv ...] [--labels a,b]   -o spread.png
                                                                     m2(t) and P^-1(t) on log-log axes
  spreading_figures.py spectra  U.csv V.csv [U2.csv V2.csv ...] [--titles "a;b"] -o spectra.png
                                                                     g(nu) of the displacements (the paper's) beside
                                                                     that of the velocities, one panel per run
  spreading_figures.py cost     BENCH.json -o cost.png             cost-accuracy of the schemes, from
                          dynamics_benchmark --benchmark_filter=CostAccuracy --benchmark_out=BENCH.json

Inputs are the tool's files as documented in DESIGN.md; nothing is recomputed here.
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{path}: no rows")
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def energy_map(args):
    import h5py

    with h5py.File(args.map, "r") as f:
        energy = np.array(f["energy"])
        t = np.array(f["t"])
        site = np.array(f["site"])
    spectrum = read_csv(args.spectrum)
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4.5), gridspec_kw={"width_ratios": [3, 1]})
    # Relative energy on a log scale, as the paper shows it; zeros (outside the front) are masked.
    total = energy.sum(axis=1, keepdims=True)
    with np.errstate(divide="ignore"):
        shown = np.log10(np.where(energy > 0, energy / total, np.nan))
    image = ax.pcolormesh(site, t * 1e3, shown, shading="auto", cmap="viridis", vmin=args.floor, vmax=0)
    fig.colorbar(image, ax=ax, label=r"$\log_{10} E_n / \sum E$")
    ax.set_xlabel("bead n")
    ax.set_ylabel("t [ms]")
    bx.semilogx(np.maximum(spectrum["g"], 1e-12), spectrum["freq_khz"], lw=0.8)
    bx.set_xlim(1e-6, 1.5)
    bx.set_xlabel(r"$g(\nu)$")
    bx.set_ylabel(r"$\nu$ [kHz]")
    fig.tight_layout()
    fig.savefig(args.output, dpi=150)


def forces(args):
    series = read_csv(args.forces)
    profile = read_csv(args.profile)
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4))
    for s in np.unique(series["site"]):
        pick = series["site"] == s
        ax.plot(series["t"][pick] * 1e3, series["force"][pick], lw=0.8, label=f"bead {int(s)}")
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("force [N]")
    ax.legend()
    bx.plot(profile["site"], profile["force"], lw=0.6)
    bx.set_xlabel("bead n")
    bx.set_ylabel("force at T [N]")
    fig.tight_layout()
    fig.savefig(args.output, dpi=150)


def spread(args):
    labels = args.labels.split(",") if args.labels else args.inputs
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4))
    for path, label in zip(args.inputs, labels):
        d = read_csv(path)
        keep = d["t"] > 0
        ax.loglog(d["t"][keep] * 1e3, d["m2"][keep], label=label)
        bx.loglog(d["t"][keep] * 1e3, d["ipr"][keep], label=label)
    ax.set_xlabel("t [ms]")
    ax.set_ylabel(r"$\tilde m_2$")
    bx.set_xlabel("t [ms]")
    bx.set_ylabel(r"$P^{-1}$")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=150)


def spectra(args):
    """g(nu) of u and of v for each run: a permanent step in u_n(t) (a velocity kick's net
    displacement) has power ~ 1/nu^2 and makes the displacement spectrum peak at 0 Hz; the
    velocity spectrum is flat under it and shows what vibrates."""
    if len(args.inputs) % 2:
        sys.exit("spectra: give pairs of files: displacement spectrum, velocity spectrum")
    pairs = [args.inputs[i:i + 2] for i in range(0, len(args.inputs), 2)]
    titles = args.titles.split(";") if args.titles else [u for u, _ in pairs]
    fig, axes = plt.subplots(1, len(pairs), figsize=(5 * len(pairs), 3.8), squeeze=False)
    for ax, (u_path, v_path), title in zip(axes[0], pairs, titles):
        for path, label, colour in ((u_path, "of $u_n$ (the paper's $g$)", "C0"), (v_path, r"of $\dot u_n$", "C1")):
            d = read_csv(path)
            ax.semilogy(d["freq_khz"], np.maximum(d["g"], 1e-14), lw=0.7, color=colour, label=label)
        ax.set_xlim(0, args.fmax)
        ax.set_ylim(1e-8, 2)
        ax.set_xlabel(r"$\nu$ [kHz]")
        ax.set_ylabel(r"$g(\nu)$ (max 1)")
        ax.set_title(title, fontsize=9)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=150)


def cost(args):
    import json

    with open(args.bench) as f:
        runs = json.load(f)["benchmarks"]
    curves = {}
    for r in runs:
        if "max_energy_error" not in r:
            continue
        curves.setdefault(r.get("label", r["name"]), []).append(
            (r["cpu_time"], r["max_energy_error"], r["final_state_error"], r["name"].split("tau_ns:")[1].split("/")[0]))
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4))
    for label, points in sorted(curves.items()):
        points.sort()
        t = [p[0] for p in points]
        ax.loglog(t, [p[1] for p in points], "o-", label=label)
        bx.loglog(t, [p[2] for p in points], "o-", label=label)
        for p in points:
            ax.annotate(f"{int(p[3]) / 1000:g}", (p[0], p[1]), fontsize=6)
    unit = runs[0].get("time_unit", "ms")
    ax.set_xlabel(f"CPU time per realization [{unit}]")
    ax.set_ylabel("max relative energy error")
    bx.set_xlabel(f"CPU time per realization [{unit}]")
    bx.set_ylabel("final-state error")
    ax.legend(fontsize=8, title=r"labels: $\tau$ [$\mu$s]", title_fontsize=7)
    fig.tight_layout()
    fig.savefig(args.output, dpi=150)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="figure", required=True)
    m = sub.add_parser("map", help="energy map beside the spectral density")
    m.add_argument("map")
    m.add_argument("spectrum")
    m.add_argument("--floor", type=float, default=-12, help="lowest log10 relative energy shown")
    f = sub.add_parser("forces", help="force series beside the force profile at T")
    f.add_argument("forces")
    f.add_argument("profile")
    s = sub.add_parser("spread", help="m2 and P^-1 versus t, log-log")
    s.add_argument("inputs", nargs="+")
    s.add_argument("--labels")
    g = sub.add_parser("spectra", help="spectral density of u beside that of v, one panel per run")
    g.add_argument("inputs", nargs="+")
    g.add_argument("--titles")
    g.add_argument("--fmax", type=float, default=60, help="highest frequency shown [kHz]")
    c = sub.add_parser("cost", help="cost-accuracy curves from the benchmark's JSON output")
    c.add_argument("bench")
    for q in (m, f, s, g, c):
        q.add_argument("-o", "--output", required=True)
    args = p.parse_args()
    {"map": energy_map, "forces": forces, "spread": spread, "spectra": spectra, "cost": cost}[args.figure](args)


if __name__ == "__main__":
    main()
