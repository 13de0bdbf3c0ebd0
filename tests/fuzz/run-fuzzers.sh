#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) and runs each for SECONDS (default 60)
# from the seed corpus in tests/fuzz/corpus/<target>, JOBS (default 2) targets at a time, each
# on one core. Fails if any target finds a crash, leak or sanitizer report; the reproducer is
# left in build-fuzz/fuzz/crash-* — turn it into a regression test (and a corpus file) before
# fixing.
# `--build-only` builds the targets and stops (tests/run-all.sh builds them while other tests run).
set -euo pipefail
seconds=${1:-60}
jobs=${JOBS:-2}
top=$(cd "$(dirname "$0")/../.." && pwd)
build="$top/build-fuzz"
CC=clang CXX=clang++ cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRANULAR_FUZZ=ON \
  -DGRANULAR_NATIVE=OFF >/dev/null
cmake --build "$build" -j"$jobs" --target fuzzers >/dev/null
[[ $seconds == --build-only ]] && exit 0
targets="range_syntax configuration_file checkpoint_log"
# The Python module's argument conversion, when the embedded-interpreter target could be built.
[[ -x $build/fuzz/fuzz_python_arguments ]] && targets="$targets python_arguments"

fuzz() {  # fuzz TARGET: runs one target; writes its verdict to $build/fuzz/TARGET.verdict
  local target=$1 corpus log leaks=1 runs
  corpus=$(mktemp -d)
  cp "$top/tests/fuzz/corpus/$target/"* "$corpus/"
  log="$build/fuzz/$target.log"
  # The embedded interpreter keeps caches and interned objects on purpose: no leak checks there.
  [[ $target == python_arguments ]] && leaks=0
  if (cd "$build/fuzz" && ASAN_OPTIONS=detect_leaks=$leaks "./fuzz_$target" -max_total_time="$seconds" -max_len=4096 \
        -rss_limit_mb=2048 -detect_leaks=$leaks \
        -print_final_stats=1 "$corpus" >"$log" 2>&1); then
    runs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}')
    echo "fuzz $target: ${runs:-?} executions in ${seconds}s, no findings" >"$build/fuzz/$target.verdict"
  else
    echo "fuzz $target: FINDING (see $log and $build/fuzz/crash-*)" >"$build/fuzz/$target.verdict"
    tail -n 30 "$log" >>"$build/fuzz/$target.verdict"
  fi
  rm -rf "$corpus"
}

running=0
for target in $targets; do
  rm -f "$build/fuzz/$target.verdict"
  fuzz "$target" &
  running=$((running + 1))
  if ((running >= jobs)); then
    wait -n || true
    running=$((running - 1))
  fi
done
wait
status=0
for target in $targets; do
  if [[ -f $build/fuzz/$target.verdict ]]; then
    cat "$build/fuzz/$target.verdict"
    grep -q 'no findings' "$build/fuzz/$target.verdict" || status=1
  else
    echo "fuzz $target: FINDING (no verdict: the run itself failed; see $build/fuzz/$target.log)"
    status=1
  fi
done
exit $status
