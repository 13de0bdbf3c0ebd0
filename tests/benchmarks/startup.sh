#!/usr/bin/env bash
# What a run pays before it computes (issue: "a tool pays only for what it uses"): for each tool,
# the best of REPEATS wall times of `TOOL --version` and the shared libraries it loads (ldd); for
# Python, `import numpy` against `import numpy, granular` (the module's own cost), best of REPEATS,
# and `import granular` timed inside a process that has imported NumPy.
# Usage: tests/benchmarks/startup.sh [BUILD_DIR] [REPEATS]. Check `uptime` first: re-run idle.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
repeats=${2:-20}
echo "startup: $(date -u +%FT%TZ), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"

best_ms() {  # best wall time [ms] of REPEATS runs of a command
  local best="" start end
  for ((r = 0; r < repeats; r++)); do
    start=$(date +%s%N)
    "$@" >/dev/null 2>&1
    end=$(date +%s%N)
    best=$(awk -v t="$(((end - start) / 1000))" -v b="$best" 'BEGIN {print (b == "" || t / 1000 < b) ? t / 1000 : b}')
  done
  echo "$best"
}

printf "%-14s %10s %10s %s\n" tool "ms" libraries "PETSc/SLEPc/HDF5/MPI loaded"
for tool in restitution correlations spectrum ipr-map localization spreading exponents butterfly breathers; do
  libs=$(ldd "$build/$tool" | wc -l)
  heavy=$(ldd "$build/$tool" | { grep -oE 'lib(petsc|slepc|hdf5|mpi)[^ ]*' || true; } | sed 's/\.so.*//' | sort -u | tr '\n' ' ')
  printf "%-14s %10.1f %10d %s\n" "$tool" "$(best_ms "$build/$tool" --version)" "$libs" "${heavy:-none}"
done
numpy=$(best_ms /usr/bin/python3 -c "import numpy")
both=$(PYTHONPATH=$build/python best_ms /usr/bin/python3 -c "import numpy, granular")
printf "python: import numpy %.1f ms, import numpy, granular %.1f ms (granular adds %.1f ms)\n" "$numpy" "$both" \
  "$(awk -v a="$both" -v b="$numpy" 'BEGIN {print a - b}')"
# The difference of two process times is within their spread (a few ms); the import alone, timed
# inside a process that has NumPy loaded already, is not.
inside=$(PYTHONPATH=$build/python /usr/bin/python3 - "$repeats" <<'PY'
import subprocess, sys
code = "import time, numpy; t = time.perf_counter(); import granular; print(time.perf_counter() - t)"
print(1e3 * min(float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                                     check=True).stdout) for _ in range(int(sys.argv[1]))))
PY
)
printf "python: import granular after numpy, timed inside the process: %.1f ms\n" "$inside"
