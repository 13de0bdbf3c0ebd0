#!/usr/bin/env bash
# Whole-process time and peak memory of `crystal --near 30 --count 20` (a mass-disordered hexagonal
# crystal, width 0.3, seed 1, walls, F0 = 10 N) per side L (L x L beads) and method, with SciPy's
# eigsh on the very same matrix side by side (tests/benchmarks/crystal_scipy.py, /usr/bin/python3).
#   tests/benchmarks/crystal_scaling.sh BUILD_DIR "100 200 316" "arpack slepc" [scipy]
set -euo pipefail
build=${1:-build}
sides=${2:-"100 200 316"}
methods=${3:-"arpack slepc"}
with_scipy=${4:-scipy}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-7s %-8s %9s %9s %10s %s\n' method beads wall_s solve_s peak_MB note
for l in $sides; do
  for m in $methods; do
    /usr/bin/time -v "$build/crystal" --lattice hexagonal --Lx "$l" --Ly "$l" --disorder mass --width 0.3 \
      --near 30 --count 20 --method "$m" --quiet --output "$work/$m" --dump-matrix "$work/matrix" \
      2> "$work/time.txt" > /dev/null || { echo "$m $l failed"; cat "$work/time.txt"; continue; }
    wall=$(grep -oP '"wall_time_s": \K[0-9.e+-]+' "$work/$m.json")
    solve=$(grep -oP '"solve_seconds": \K[0-9.e+-]+' "$work/$m.json")
    rss=$(grep -oP 'Maximum resident set size \(kbytes\): \K[0-9]+' "$work/time.txt")
    printf '%-7s %-8s %9.2f %9.2f %10.1f %s\n' "$m" "$((l * l))" "$wall" "$solve" \
      "$(awk -v k="$rss" 'BEGIN{print k/1024}')" "in-tool wall (packing + static state + matrix + solve + output)"
  done
  if [[ $with_scipy == scipy ]]; then
    ref=$(ls "$work"/*.csv | head -1)
    /usr/bin/time -v /usr/bin/python3 "$here/crystal_scipy.py" "$work/matrix" 30 20 "$ref" > "$work/scipy.json" \
      2> "$work/time.txt"
    rss=$(grep -oP 'Maximum resident set size \(kbytes\): \K[0-9]+' "$work/time.txt")
    secs=$(grep -oP '"seconds": \K[0-9.e+-]+' "$work/scipy.json")
    printf '%-7s %-8s %9s %9.2f %10.1f %s\n' scipy "$((l * l))" - "$secs" "$(awk -v k="$rss" 'BEGIN{print k/1024}')" \
      "eigsh alone (SuperLU); max rel freq diff vs ours $(grep -oP '"max_rel_freq_diff_vs_ours": \K[0-9.e+-]+' "$work/scipy.json")"
  fi
done
