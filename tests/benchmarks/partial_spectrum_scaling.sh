#!/usr/bin/env bash
# Whole-process time and peak memory of `spectrum --near` for K = 20 modes nearest 15 kHz of an
# Anderson chain (ξ = q = 0.5, F0 = 10 N, seed 1), per method and N, with SciPy's eigsh on the very
# same matrix side by side (tests/benchmarks/scipy_eigsh.py, /usr/bin/python3). Prints a table.
#   tests/benchmarks/partial_spectrum_scaling.sh BUILD_DIR "1e5 1e6 1e7" "bisect lapack arpack slepc" [scipy]
set -euo pipefail
build=${1:-build}
sizes=${2:-"100000 1000000 10000000"}
methods=${3:-"bisect lapack arpack slepc"}
with_scipy=${4:-scipy}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-8s %-10s %10s %12s %s\n' method N wall_s peak_rss_MB note
for n in $sizes; do
  n=$(printf '%.0f' "$n")
  for m in $methods; do
    /usr/bin/time -v "$build/spectrum" --N "$n" --near 15 --count 20 --method "$m" --quiet \
      --output "$work/$m.csv" --dump-matrix "$work/matrix" 2> "$work/time.txt" > /dev/null || { echo "$m $n failed"; cat "$work/time.txt"; continue; }
    wall=$(grep -oP '"wall_time_s": \K[0-9.e+-]+' "$work/$m.json")
    rss=$(grep -oP 'Maximum resident set size \(kbytes\): \K[0-9]+' "$work/time.txt")
    printf '%-8s %-10s %10.3f %12.1f %s\n' "$m" "$n" "$wall" "$(awk -v k="$rss" 'BEGIN{print k/1024}')" "in-tool wall time (chain + matrix + solve + output)"
  done
  if [[ $with_scipy == scipy ]]; then
    ref=$(ls "$work"/*.csv | head -1)
    /usr/bin/time -v /usr/bin/python3 "$here/scipy_eigsh.py" "$work/matrix" 15 20 "$ref" > "$work/scipy.json" 2> "$work/time.txt"
    rss=$(grep -oP 'Maximum resident set size \(kbytes\): \K[0-9]+' "$work/time.txt")
    printf '%-8s %-10s %10.3f %12.1f %s\n' scipy "$n" "$(grep -oP '"seconds": \K[0-9.e+-]+' "$work/scipy.json")" \
      "$(awk -v k="$rss" 'BEGIN{print k/1024}')" "eigsh only; $(grep -oP '"max_rel_freq_diff_vs_ours": \K[0-9.e+-]+' "$work/scipy.json") max rel freq diff"
  fi
done
