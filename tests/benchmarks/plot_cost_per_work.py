#!/usr/bin/python3
"""The figure of cost_per_work.sh: cost per unit of work [ns] against N, one line per job, log-log.

usage: /usr/bin/python3 tests/benchmarks/plot_cost_per_work.py cost-per-work.csv [-o cost-per-work.png]"""
import argparse
import csv
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("csv")
parser.add_argument("-o", "--output", default="cost-per-work.png")
args = parser.parse_args()
series = defaultdict(list)
with open(args.csv) as f:
    for row in csv.DictReader(f):
        series[row["job"]].append((int(row["N"]), float(row["ns_per_unit"])))
units = {"spectrum fast": "per mode x element", "spectrum bisect": "per bead (20 modes)",
         "ipr-map": "per chain x mode x element", "localization": "per bead x frequency",
         "spreading": "per bead x step"}
fig, ax = plt.subplots(figsize=(7, 4.5))
for job, points in series.items():
    points.sort()
    ax.loglog([p[0] for p in points], [p[1] for p in points], "o-", label=f"{job} ({units.get(job, '')})")
ax.set_xlabel("beads N")
ax.set_ylabel("wall time per unit of work [ns], whole process")
ax.set_title("Cost per unit of work against N (start-up included)")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(args.output, dpi=120)
print(args.output)
