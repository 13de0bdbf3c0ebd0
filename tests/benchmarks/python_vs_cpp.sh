#!/usr/bin/env bash
# Does calling from Python cost the C++ speed? (the default IPR map from Python within
# 10 % of the ipr-map tool; 1000 small spectrum calls within 2x of the same loop in C++.)
#   1. the default IPR map (Anderson, xi = 0.1:1:0.01, q = 0.2/0.5/0.8, N = 100, 100 realizations,
#      all cores): whole process, `ipr-map` against `python3 -c "import granular; granular.ipr_map()"`,
#      wall time, median of REPEATS, the two interleaved so that load from others hits both alike;
#      plus the Python call alone (without interpreter start and import);
#   2. a loop of COUNT spectrum calls on chains of N beads (new chain each time, every mode, LAPACK):
#      the C++ program spectrum_loop against the same loop in Python, in-process wall time,
#      median of REPEATS, for each N in SIZES;
#   3. two IPR maps on two Python threads against the same two calls one after the other, and two
#      ipr-map processes together against one after the other: what two cores give right now
#      (~0.5 on an idle 2-core machine; 1 for calls that held the GIL), median of REPEATS.
# Usage: tests/benchmarks/python_vs_cpp.sh [BUILD_DIR] [REPEATS] [SIZES] [COUNT]
# Needs a Release build with GRANULAR_BENCHMARKS=ON (for benchmarks/spectrum_loop) and the Python
# module (GRANULAR_PYTHON, on by default). Times on a busy machine are not final: re-run idle.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
repeats=${2:-5}
sizes=${3:-"20 100"}
count=${4:-1000}
python=/usr/bin/python3
export PYTHONPATH=$build/python
for f in "$build/ipr-map" "$build/benchmarks/spectrum_loop" "$build/python/granular/__init__.py"; do
  [[ -e $f ]] || { echo "python_vs_cpp: missing $f (configure with -DGRANULAR_BENCHMARKS=ON and build)" >&2; exit 1; }
done
out=$(mktemp -d /tmp/python-vs-cpp.XXXXXX)
echo "python_vs_cpp: $(date -u +%FT%TZ), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), files in $out"

median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
wall() {  # seconds of wall time of a command
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN {print b - a}'
}

# --- 1. the default IPR map --------------------------------------------------------------------
: >"$out/tool" ; : >"$out/python" ; : >"$out/python-call"
for ((r = 0; r < repeats; r++)); do
  wall "$build/ipr-map" --quiet --output "$out/ipr-map.csv" >>"$out/tool"
  wall "$python" -c "import granular; granular.ipr_map()" >>"$out/python"
  "$python" -c "import time, granular; t = time.perf_counter(); granular.ipr_map(); print(time.perf_counter() - t)" \
    >>"$out/python-call"
done
tool=$(median <"$out/tool")
py=$(median <"$out/python")
call=$(median <"$out/python-call")
printf "default IPR map, whole process (median of %d): ipr-map %.3f s, Python %.3f s (%+.1f %%); " \
  "$repeats" "$tool" "$py" "$(awk -v a="$py" -v b="$tool" 'BEGIN {print 100 * (a / b - 1)}')"
printf "the Python call alone %.3f s (%+.1f %%)\n" "$call" "$(awk -v a="$call" -v b="$tool" 'BEGIN {print 100 * (a / b - 1)}')"

# --- 2. a loop of small spectrum calls -----------------------------------------------------------
for n in $sizes; do
  cpp=$("$build/benchmarks/spectrum_loop" "$n" "$count" "$repeats" | cut -d' ' -f1)
  py=$("$python" "$root/tests/benchmarks/spectrum_loop.py" "$n" "$count" "$repeats")
  printf "%d spectrum calls, N = %d (median of %d): C++ %.4f s, Python %.4f s (%.2fx)\n" \
    "$count" "$n" "$repeats" "$cpp" "$py" "$(awk -v a="$py" -v b="$cpp" 'BEGIN {print a / b}')"
done

# --- 3. two calls on two Python threads ------------------------------------------------------------
: >"$out/processes"
run_map() { "$build/ipr-map" --xi 0.1:0.6 --q 0.5 --N 100 --realizations 40 --threads 1 --quiet --output "$out/map$1.csv"; }
maps_in_turn() { run_map 0; run_map 1; }
maps_together() { run_map 0 & run_map 1 & wait; }
for ((r = 0; r < repeats; r++)); do
  awk -v a="$(wall maps_together)" -v b="$(wall maps_in_turn)" 'BEGIN {print a / b}' >>"$out/processes"
done
threads=$("$python" "$root/tests/benchmarks/two_threads.py" "$repeats")
printf "two IPR maps at once / one after the other (median of %d): two Python threads %.2f, two processes %.2f\n" \
  "$repeats" "$threads" "$(median <"$out/processes")"
