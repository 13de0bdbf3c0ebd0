#!/usr/bin/env bash
# `localization` against a NumPy transfer-matrix loop (localization_numpy.py, vectorized over
# frequencies) at 1000 frequencies (0.05:50:0.05 kHz) on a 10^7-bead Anderson chain (ξ = q = 0.5,
# F0 = 10 N), side by side, plus the tool's peak memory at N = 10^6 and 10^7.
#
#   bash tests/benchmarks/localization_vs_numpy.sh [BUILD_DIR] [NUMPY_N]
#
# NumPy takes ~10 µs per bead for 1000 frequencies (≈ 2 minutes per 10^7 beads), so by default it
# runs on the first NUMPY_N = 10^6 beads of the same chain and its time is extrapolated linearly
# to 10^7 (the loop is O(N) with nothing else growing); NUMPY_N=10000000 runs it in full. Both
# codes read the same types file; on the NUMPY_N-bead chain their λ and IDOS are compared.
# Run on an idle machine: timings under load mean little.
set -euo pipefail
build=${1:-build}
numpy_n=${2:-1000000}
n=10000000
freqs=0.05:50:0.05
here=$(cd "$(dirname "$0")" && pwd)
tool=$(cd "$build" && pwd)/localization
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
py=/usr/bin/python3

measure() {  # label, command...: prints wall seconds and peak memory
  local label=$1; shift
  /usr/bin/time -f "%e %M" -o "$work/time" "$@" >/dev/null
  read -r secs kb <"$work/time"
  awk -v l="$label" -v s="$secs" -v k="$kb" 'BEGIN { printf "%-66s %8.2f s %8.1f MB\n", l, s, k / 1024 }'
  echo "$secs" >"$work/last"
}

echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
"$py" "$here/localization_numpy.py" --write-types "$work/chain.types" --N "$n" --q 0.5 --seed 1
head -n "$numpy_n" "$work/chain.types" >"$work/small.types"

common="--xi 0.5 --F0 10 --f $freqs --quiet"
measure "localization, streamed A chain, N = 1e6, 2 threads" \
  "$tool" --disorder A --q 0.5 --N 1e6 $common --threads 2 --output "$work/s6"
measure "localization, streamed A chain, N = 1e7, 1 thread" \
  "$tool" --disorder A --q 0.5 --N 1e7 $common --threads 1 --output "$work/s7a"
measure "localization, streamed A chain, N = 1e7, 2 threads" \
  "$tool" --disorder A --q 0.5 --N 1e7 $common --threads 2 --output "$work/s7"
cmp -s "$work/s7a.csv" "$work/s7.csv" && echo "  (1 and 2 threads: identical CSV)"
measure "localization, --config file of N = 1e7 (NumPy's chain), 2 thr." \
  "$tool" --config "$work/chain.types" $common --threads 2 --output "$work/file"
tool_secs=$(cat "$work/last")
measure "localization, --config file of N = $numpy_n, 2 threads" \
  "$tool" --config "$work/small.types" $common --threads 2 --output "$work/small"
measure "NumPy (localization_numpy.py), N = $numpy_n" \
  "$py" "$here/localization_numpy.py" --types "$work/small.types" --xi 0.5 --F0 10 --f "$freqs" --output "$work/numpy.csv"
numpy_secs=$(cat "$work/last")

"$py" - "$work/small.csv" "$work/numpy.csv" "$numpy_n" <<'EOF'
import csv, sys
tool = list(csv.DictReader(open(sys.argv[1])))
ref = list(csv.DictReader(open(sys.argv[2])))
n = int(sys.argv[3])
assert len(tool) == len(ref) == 1000, (len(tool), len(ref))
worst = max(abs(float(a["lyapunov"]) - float(b["lyapunov"])) for a, b in zip(tool, ref))
counts = sum(round(float(a["idos"]) * n) != round(float(b["idos"]) * n) for a, b in zip(tool, ref))
print(f"  same chain, N = {n}: max |lambda_tool - lambda_numpy| = {worst:.2e} /bead; IDOS counts differing: {counts} of 1000")
EOF
echo "$numpy_secs $numpy_n $n $tool_secs" | awk '{ t = $1 * $3 / $2;
  printf "NumPy extrapolated to N = %d: %.0f s (%.2f s x %g); localization on the same file: %.2f s; ratio %.0fx\n",
         $3, t, $1, $3 / $2, $4, t / $4 }'
