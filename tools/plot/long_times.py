#!/usr/bin/python3
"""The long-time study's report: merges the per-case `exponents` runs of
tests/benchmarks/long-time-study.sh into one run, OUTPUT_DIR/all.{csv,json} with -curves.csv and
-profiles.csv (so `python3 -m granular.plot exponents OUTPUT_DIR/all --all` draws it), prints a
markdown table of gamma and eta at T = 100 ms beside the 10 ms study of record (default
docs/results/exponents.csv: N = 2501, 500 realizations, fit 4-10 ms) with each case's N, scheme,
wall time and share of the study, and draws OUTPUT_DIR/long-times-exponents.png (both exponents
at both times) and OUTPUT_DIR/all-spreading-<kick>.png (m2, P^-1 and L_d to 100 ms).

usage: /usr/bin/python3 tools/plot/long_times.py OUTPUT_DIR [--reference PREFIX.csv]
The figures are granular.plot.study_comparison and granular.plot.exponents (`python3 -m
granular.plot study-comparison` and `exponents`).
"""
import argparse
import csv
import glob
import json
import math
import os
import sys

from _granular import plot_main

ORDER = {"h": 0, "A": 1, "RDM1": 2, "RDM2": 3}


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def merge(folder):
    """Concatenates every case's CSVs into folder/all*; returns (rows, cases from the JSONs)."""
    prefixes = sorted(p[:-5] for p in glob.glob(os.path.join(folder, "*.json")) if os.path.basename(p) != "all.json")
    if not prefixes:
        raise SystemExit(f"long_times.py: no exponents runs (*.json) in {folder}")
    rows, cases, meta = [], [], None
    for suffix in (".csv", "-curves.csv", "-profiles.csv"):
        out = os.path.join(folder, "all" + suffix)
        with open(out + ".tmp", "w", newline="") as f:
            writer = None
            for prefix in prefixes:
                part = read_rows(prefix + suffix)
                if writer is None and part:
                    writer = csv.DictWriter(f, fieldnames=list(part[0].keys()), lineterminator="\n")
                    writer.writeheader()
                if writer:
                    writer.writerows(part)
                if suffix == ".csv":
                    rows += part
        os.replace(out + ".tmp", out)
    for prefix in prefixes:
        with open(prefix + ".json") as f:
            m = json.load(f)
        meta = meta or m
        for c in m["cases"]:
            c["run"] = os.path.basename(prefix)
            c.pop("exponents", None)
            cases.append(c)
    merged = {k: meta[k] for k in ("tool", "version", "parameters", "time_step_rule") if k in meta}
    merged["cases"] = cases
    merged["merged_from"] = [os.path.basename(p) for p in prefixes]
    with open(os.path.join(folder, "all.json"), "w") as f:
        json.dump(merged, f, indent=1)
    return rows, cases


def key(r):
    return (r["ic"], float(r["F0"]), r["disorder"])


def cell(r, name):
    star = " *" if r[name + "_star"] == "true" else ""
    return f"{float(r[name]):.3f} ± {float(r[name + '_real_err']):.3f}{star}"


def shift(a, b, name):
    """(b − a) in units of the realization errors added in quadrature."""
    d = float(b[name]) - float(a[name])
    s = math.hypot(float(a[name + "_real_err"]), float(b[name + "_real_err"]))
    return f"{d:+.3f} ({d / s:+.1f}σ)" if s > 0 else f"{d:+.3f}"


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("folder")
    p.add_argument("--reference", default=os.path.join(os.path.dirname(__file__), "..", "..", "docs", "results",
                                                        "exponents.csv"))
    args = p.parse_args()
    rows, cases = merge(args.folder)
    short = {key(r): r for r in read_rows(args.reference)}
    times = {r["case"]: r for r in read_rows(os.path.join(args.folder, "times.csv"))}
    total_wall = sum(float(t["wall_s"]) for t in times.values())
    total_cpu = sum(float(t["cpu_s"]) for t in times.values())
    by_case = {(c["ic"], float(c["F0_N"]), c["disorder"]): c for c in cases}
    print("| kick | F0 [N] | chain | N | scheme, τ | γ 10 ms | γ 100 ms | Δγ | η 10 ms | η 100 ms | Δη "
          "| real. (excl.) | max energy error | wall [s] | share |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(rows, key=lambda r: (r["ic"] != "displacement", -float(r["F0"]), ORDER.get(r["disorder"], 9))):
        k, c = key(r), by_case[key(r)]
        s = short.get(k)
        run = times.get(c["run"], {})
        wall = float(run.get("wall_s", "nan"))
        shared = c["disorder"] == "h"  # the ten homogeneous cases share one timed run
        wall_text = f"{wall:.1f}" + (" (10 cases)" if shared else "")
        print(f"| {k[0]} | {k[1]:g} | {k[2]} | {c['N']} | {c['integrator']}, {c.get('time_step', c.get('dt_s')) * 1e6:g} µs "
              f"| {cell(s, 'gamma') if s else '—'} | {cell(r, 'gamma')} | {shift(s, r, 'gamma') if s else '—'} "
              f"| {cell(s, 'eta') if s else '—'} | {cell(r, 'eta')} | {shift(s, r, 'eta') if s else '—'} "
              f"| {r['realizations']} ({len(c.get('failed_excluded', []))}) | {float(r['max_energy_error']):.1e} "
              f"| {wall_text} | {100 * wall / total_wall:.1f} %{' (all h)' if shared else ''} |")
    peak = max(float(t["max_rss_kB"]) for t in times.values()) / 1024
    print(f"\n{len(rows)} cases in {len(times)} runs: {total_wall:.0f} s wall "
          f"({total_wall / 60:.1f} min), {total_cpu:.0f} s CPU, peak memory {peak:.0f} MB (largest run).")
    codes = [plot_main(["exponents", os.path.join(args.folder, "all"), "--kick", kick], "long_times.py")
             for kick in sorted({r["ic"] for r in rows})]
    codes.append(plot_main(["study-comparison", os.path.join(args.folder, "all"), args.reference, "-o",
                            os.path.join(args.folder, "long-times-exponents.png"), "--dpi", "110"], "long_times.py"))
    return max(codes)


if __name__ == "__main__":
    sys.exit(main())
