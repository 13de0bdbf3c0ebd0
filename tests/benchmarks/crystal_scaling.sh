#!/usr/bin/env bash
# Whole-process time and peak memory of `crystal --near KHZ --count 20` (a mass-disordered hexagonal
# crystal, width 0.3, seed 1, walls, F0 = 10 N) per side L (L x L beads) and method, with SciPy's
# eigsh on the very same matrix side by side (tests/benchmarks/crystal_scipy.py, /usr/bin/python3).
#   tests/benchmarks/crystal_scaling.sh BUILD_DIR "100 200 316" "arpack slepc slepc2" [scipy|none] [KHZ] [OUT.csv]
# slepc2 is `mpirun -n 2 crystal --method slepc`. KHZ defaults to 15, inside the band (about 0.5 ...
# 22 kHz for this crystal): a target above the band is refused (Gershgorin's bound). OUT.csv gets one
# row per run (method,beads,wall_s,solve_s,peak_mb); tests/benchmarks/crystal_scaling_plot.py draws it.
set -euo pipefail
build=${1:-build}
sides=${2:-"100 200 316"}
methods=${3:-"arpack slepc"}
with_scipy=${4:-scipy}
khz=${5:-15}
csv=${6:-}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
[[ -n $csv ]] && echo "method,beads,wall_s,solve_s,peak_mb" > "$csv"
row() { [[ -n $csv ]] && echo "$1,$2,$3,$4,$5" >> "$csv"; printf '%-7s %-8s %9s %9.2f %10.1f %s\n' "$@"; }
printf '%-7s %-8s %9s %9s %10s %s\n' method beads wall_s solve_s peak_MB note
for l in $sides; do
  dumped=
  for m in $methods; do
    run=("$build/crystal") method=$m
    [[ $m == slepc2 ]] && run=(mpirun -n 2 "$build/crystal") method=slepc
    dump=()
    [[ -z $dumped ]] && dump=(--dump-matrix "$work/matrix") dumped=$m
    /usr/bin/time -v "${run[@]}" --lattice hexagonal --Lx "$l" --Ly "$l" --disorder mass --width 0.3 \
      --near "$khz" --count 20 --method "$method" --quiet --output "$work/$m" "${dump[@]}" \
      2> "$work/time.txt" > /dev/null || { echo "$m $l failed"; cat "$work/time.txt"; exit 1; }
    wall=$(grep -oP '"wall_time_s": \K[0-9.e+-]+' "$work/$m.json")
    solve=$(grep -oP '"solve_seconds": \K[0-9.e+-]+' "$work/$m.json")
    # mpirun's peak is its largest child's (one rank's), as /usr/bin/time reports it
    rss=$(grep -oP 'Maximum resident set size \(kbytes\): \K[0-9]+' "$work/time.txt")
    row "$m" "$((l * l))" "$(printf %.2f "$wall")" "$solve" "$(awk -v k="$rss" 'BEGIN{print k/1024}')" \
      "in-tool wall (packing + static state + matrix + solve + output)"
  done
  if [[ $with_scipy == scipy ]]; then
    /usr/bin/time -v /usr/bin/python3 "$here/crystal_scipy.py" "$work/matrix" "$khz" 20 "$work/$dumped.csv" \
      > "$work/scipy.json" 2> "$work/time.txt"
    rss=$(grep -oP 'Maximum resident set size \(kbytes\): \K[0-9]+' "$work/time.txt")
    secs=$(grep -oP '"seconds": \K[0-9.e+-]+' "$work/scipy.json")
    row scipy "$((l * l))" "" "$secs" "$(awk -v k="$rss" 'BEGIN{print k/1024}')" \
      "eigsh alone (SuperLU); max rel freq diff vs ours $(grep -oP '"max_rel_freq_diff_vs_ours": \K[0-9.e+-]+' "$work/scipy.json")"
  fi
  rm -f "$work"/matrix.*
done
