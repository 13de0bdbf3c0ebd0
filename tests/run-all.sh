#!/usr/bin/env bash
# Builds and runs every test, in three passes (CI runs this through the README's test command),
# after a cheap first check that every C++ file is formatted as .clang-format says
# (tests/format-check.sh; GRANULAR_SKIP_FORMAT=1 skips it, for local runs on unformatted branches):
#   1. the Release build with warnings as errors: every GoogleTest suite and tool test (ctest),
#      the Python suite, the documentation site and examples; not the label `manual` (the full
#      `pip install .` build, 11 min: `ctest -L manual`);
#      then the suites whose numbers pass through BLAS/LAPACK once more on the reference BLAS
#      (pass 1b; the long breather, Newton–Krylov and ARPACK ones do so in pass 1, as the ctest
#      tests reference_blas.*, tests/CMakeLists.txt);
#   2. the same suites built with clang, AddressSanitizer + UndefinedBehaviorSanitizer (any report fails);
#   3. the threaded suites (ensembles, IPR map, localization, bootstrap) built with clang and
#      ThreadSanitizer, OpenMP through LLVM's libomp with its archer tool (any report fails);
#   4. each libFuzzer target for FUZZ_SECONDS (default 60) from its seed corpus.
# Set GRANULAR_QUICK=1 to run pass 1 only. Ends with one line "summary: N passed, 0 failed".
# Each pass's build starts, at a lower priority, while the previous pass's tests run: the tests
# leave part of the two cores idle (processes that wait on each other, serial steps), and the
# build takes what they leave. Its output goes to a log, printed if it fails.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
jobs=${JOBS:-2}
logs=$(mktemp -d)
passed=0

count() {  # adds the passed tests of a ctest log to $passed
  local line total failed
  line=$(grep -E '[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$1" | tail -n 1)
  total=$(sed -E 's/.*out of ([0-9]+).*/\1/' <<<"$line")
  failed=$(sed -E 's/.* ([0-9]+) tests? failed.*/\1/' <<<"$line")
  passed=$((passed + total - failed))
}

stamp() { echo "== $* ($(date +%T))"; }

background=()
trap 'for pid in "${background[@]}"; do kill -- "-$pid" 2>/dev/null || true; done' EXIT
start_build() {  # start_build NAME COMMAND...: runs a build in the background, niced, logged
  local name=$1
  shift
  set -m
  (renice -n 10 "$BASHPID" >/dev/null && "$@" >"$logs/$name.log" 2>&1) &
  set +m
  background+=($!)
  eval "pid_$name=$!"
}
finish_build() {  # finish_build NAME: waits for a background build; prints its log if it failed
  local name=$1 pid
  pid=$(eval echo "\$pid_$name")
  if ! wait "$pid"; then
    cat "$logs/$name.log"
    echo "run-all: the $name build failed" >&2
    exit 1
  fi
  stamp "$name build done"
}

if [ "${GRANULAR_SKIP_FORMAT:-0}" != 1 ]; then
  echo "== format check"
  bash tests/format-check.sh
  passed=$((passed + 1))
fi

# Pass 2 with clang (pass 1 is GCC): its UBSan also checks pointer arithmetic, and with ASan + UBSan
# it compiles ~1.3x faster than GCC 12 (docs/reliability.md, "Sanitizers").
build_sanitize() {
  CC=clang CXX=clang++ cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRANULAR_SANITIZE=ON -DGRANULAR_BENCHMARKS=OFF \
    -DGRANULAR_NATIVE=OFF && cmake --build build-sanitize -j"$jobs"
}
build_tsan() {
  CC=clang CXX=clang++ cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRANULAR_TSAN=ON \
    -DGRANULAR_BENCHMARKS=OFF -DGRANULAR_PYTHON=OFF -DGRANULAR_NATIVE=OFF &&
    cmake --build build-tsan -j"$jobs" --target test_threaded
}
quick() { [ "${GRANULAR_QUICK:-0}" = 1 ]; }

# Tests whose numbers pass through BLAS/LAPACK, run again on the reference BLAS (pass 1b).
blas_tests='Spectrum|Lapack|Arpack|Slepc|Partial|MethodsAgree|PeriodicOrbit|Breather|Floquet|ModeIpr|IprMap|BandEdges'

stamp "pass 1: Release build, all tests"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGRANULAR_WERROR=ON >/dev/null
cmake --build build -j"$jobs"
stamp "pass 1 build done"
quick || start_build sanitize build_sanitize
ctest --test-dir build -j"$jobs" --output-on-failure -LE manual | tee "$logs/pass1"
count "$logs/pass1"
# The suites whose results go through BLAS/LAPACK (spectra by LAPACK, ARPACK and SLEPc; shooting
# and Floquet by dgesv/dgeev) once more on Debian's reference BLAS, when the alternatives picked
# another one (OpenBLAS, from tools/install-deps.sh): their tolerances must hold on both.
reference_blas=/usr/lib/x86_64-linux-gnu/blas
if [ -e "$reference_blas/libblas.so.3" ] && ! ./build/spectrum --version | grep -q "BLAS: $reference_blas/"; then
  stamp "pass 1b: the linear-algebra suites on the reference BLAS"
  LD_LIBRARY_PATH="$reference_blas:/usr/lib/x86_64-linux-gnu/lapack${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
    ctest --test-dir build -j"$jobs" --output-on-failure -LE "manual|long" \
    -R "$blas_tests" | tee "$logs/pass1b"
  count "$logs/pass1b"
fi

if ! quick; then
  stamp "pass 2: AddressSanitizer + UndefinedBehaviorSanitizer"
  finish_build sanitize
  start_build tsan build_tsan
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:suppressions="$top/tests/sanitizer-suppressions.txt"
  export LSAN_OPTIONS=suppressions="$top/tests/lsan-suppressions.txt"
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # Tests that start MPI (mpirun, or PETSc/SLEPc in-process).
  mpi_tests='MpiRanks|slepc_mpi|PartialSpectrum|MethodsAgree|partial_spectrum|NodeCountCheck|tool_components|SlepcSparse|CrystalTool.NearestModes|CrystalTool.BadInput|CrystalIprMapTool.WritesTheLibrarysMap'
  ctest --test-dir build-sanitize -j"$jobs" --output-on-failure -LE long -E "$mpi_tests" | tee "$logs/pass2"
  count "$logs/pass2"
  # Once MPI is initialised (mpirun, or PETSc/SLEPc in-process), Open MPI's dlopen'ed plugins and
  # PETSc's registries leak by design and the plugins' frames cannot be named in a suppression
  # (they are unloaded before LeakSanitizer reports): for those tests leak checks are off, the
  # rest of ASan and UBSan stays on.
  ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 \
    ctest --test-dir build-sanitize -j"$jobs" --output-on-failure -R "$mpi_tests" | tee "$logs/pass2-mpi"
  count "$logs/pass2-mpi"

  stamp "pass 3: ThreadSanitizer (threaded suites)"
  finish_build tsan
  start_build fuzz bash tests/fuzz/run-fuzzers.sh --build-only
  # archer tells TSan about libomp's barriers and tasks; libomp itself is not instrumented, so its
  # internals are ignored (archer's own advice). Checked to fail on an unreduced `sum +=` in a loop.
  OMP_TOOL_LIBRARIES=/usr/lib/llvm-14/lib/libarcher.so \
    TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1 \
    ctest --test-dir build-tsan -j"$jobs" --output-on-failure | tee "$logs/pass3"
  count "$logs/pass3"

  stamp "pass 4: fuzzers"
  finish_build fuzz
  bash tests/fuzz/run-fuzzers.sh "${FUZZ_SECONDS:-60}" | tee "$logs/pass4"
  passed=$((passed + $(grep -c 'no findings' "$logs/pass4")))
fi
stamp "all passes done"
rm -rf "$logs"
echo "summary: $passed passed, 0 failed"
