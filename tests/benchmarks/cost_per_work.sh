#!/usr/bin/env bash
# No cliffs: the cost per unit of work of five jobs as N grows, whole process (start-up included),
# best of REPEATS wall times. Flat, or growing as the method's order says, is what should come out;
# a step up at some N is a cliff (a cache level, a switch of algorithm, memory).
#   spectrum --method fast   every mode and its IPR        work N^2 (mode x element)
#   spectrum --method bisect 20 modes near 15 kHz           work N   (bead)
#   ipr-map --solver fast    20 chains, every mode          work 20 N^2
#   localization             51 frequencies (0:50:1 kHz)    work 51 N (bead x frequency)
#   spreading                one run, 100 steps, no window  work 100 N (bead x step)
# Writes CSV job,N,seconds,work,ns_per_unit to OUT (and stdout); tests/benchmarks/plot_cost_per_work.py
# draws it. Usage: tests/benchmarks/cost_per_work.sh [BUILD_DIR] [REPEATS] [OUT]
# COST_MAX_N (default 1e7) leaves out larger N (a smoke test sets it small).
# Times on a busy machine are not final: check `uptime` first and re-run idle.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
repeats=${2:-3}
out=${3:-cost-per-work.csv}
work_dir=$(mktemp -d /tmp/cost-per-work.XXXXXX)
trap 'rm -rf "$work_dir"' EXIT
echo "cost_per_work: $(date -u +%FT%TZ), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)" >&2

best() {  # best wall time [s] of REPEATS runs of a command
  local best="" start end t
  for ((r = 0; r < repeats; r++)); do
    start=$(date +%s.%N)
    "$@" >/dev/null 2>&1
    end=$(date +%s.%N)
    t=$(awk -v a="$start" -v b="$end" 'BEGIN {print b - a}')
    best=$(awk -v a="$t" -v b="$best" 'BEGIN {print (b == "" || a < b) ? a : b}')
  done
  echo "$best"
}

max_n=$(printf '%.0f' "${COST_MAX_N:-1e7}")
row() {  # job N work command...
  local job=$1 n=$2 work=$3
  shift 3
  ((n <= max_n)) || return 0
  local s
  s=$(best "$@")
  awk -v j="$job" -v n="$n" -v s="$s" -v w="$work" 'BEGIN {printf "%s,%d,%.6f,%.6g,%.4g\n", j, n, s, w, 1e9 * s / w}'
}

{
  echo "job,N,seconds,work,ns_per_unit"
  for n in 100 300 1000 3000 10000 30000; do
    row "spectrum fast" $n "$((n * n))" "$build/spectrum" --N $n --method fast --quiet --output "$work_dir/s"
  done
  for n in 1000 10000 100000 1000000 10000000; do
    row "spectrum bisect" $n $n "$build/spectrum" --N $n --near 15 --count 20 --method bisect --quiet \
      --output "$work_dir/b"
  done
  for n in 100 300 1000 3000; do
    row "ipr-map" $n "$((20 * n * n))" "$build/ipr-map" --N $n --xi 0.5 --q 0.5 --realizations 20 --quiet \
      --output "$work_dir/m"
  done
  for n in 1000 10000 100000 1000000 10000000; do
    row "localization" $n "$((51 * n))" "$build/localization" --N $n --f 0:50:1 --output "$work_dir/l"
  done
  for n in 101 1001 10001 100001 1000001; do
    row "spreading" $n "$((100 * n))" "$build/spreading" --N $n --T 1e-4 --active-window off --quiet \
      --output "$work_dir/d"
  done
} | tee "$out"
