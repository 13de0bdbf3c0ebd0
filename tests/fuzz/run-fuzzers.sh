#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) and runs each for SECONDS (default 60)
# from the seed corpus in tests/fuzz/corpus/<target>. Fails if any target finds a crash, leak
# or sanitizer report; the reproducer is left in build-fuzz/fuzz/crash-* — turn it into a
# regression test (and a corpus file) before fixing.
set -euo pipefail
seconds=${1:-60}
top=$(cd "$(dirname "$0")/../.." && pwd)
build="$top/build-fuzz"
CC=clang CXX=clang++ cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRANULAR_FUZZ=ON \
  -DGRANULAR_NATIVE=OFF >/dev/null
cmake --build "$build" -j2 >/dev/null
status=0
targets="range_syntax configuration_file checkpoint_log"
# The Python module's argument conversion, when the embedded-interpreter target could be built.
[[ -x $build/fuzz/fuzz_python_arguments ]] && targets="$targets python_arguments"
for target in $targets; do
  corpus=$(mktemp -d)
  cp "$top/tests/fuzz/corpus/$target/"* "$corpus/"
  log="$build/fuzz/$target.log"
  # The embedded interpreter keeps caches and interned objects on purpose: no leak checks there.
  leaks=1
  [[ $target == python_arguments ]] && leaks=0
  if (cd "$build/fuzz" && ASAN_OPTIONS=detect_leaks=$leaks "./fuzz_$target" -max_total_time="$seconds" -max_len=4096 \
        -rss_limit_mb=2048 -detect_leaks=$leaks \
        -print_final_stats=1 "$corpus" >"$log" 2>&1); then
    runs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}')
    echo "fuzz $target: ${runs:-?} executions in ${seconds}s, no findings"
  else
    echo "fuzz $target: FINDING (see $log and $build/fuzz/crash-*)"
    tail -n 30 "$log"
    status=1
  fi
  rm -rf "$corpus"
done
exit $status
