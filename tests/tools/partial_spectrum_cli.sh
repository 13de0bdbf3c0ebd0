#!/usr/bin/env bash
# The partial-spectrum command-line contract: bad selections end with exit code 2, a one-line
# message naming the option, and no output file; edge cases that have an answer give it.
# usage: partial_spectrum_cli.sh TOOL WORKDIR [METHODS]   (METHODS default: "lapack bisect arpack slepc")
set -uo pipefail
tool=$1 work=$2 methods=${3:-"lapack bisect arpack slepc"}
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

expect_error() {  # expect_error OPTION-NAMED-IN-MESSAGE ARGS...
  local named=$1; shift
  local err
  err=$("$tool" --N 100 --quiet --output "$work/bad.csv" "$@" 2>&1 >/dev/null)
  local code=$?
  [[ $code -eq 2 ]] || fail "$* -> exit $code (want 2): $err"
  [[ $(printf '%s\n' "$err" | wc -l) -eq 1 ]] || fail "$* -> message not one line: $err"
  [[ $err == *"$named"* ]] || fail "$* -> message does not name $named: $err"
  [[ ! -e $work/bad.csv && ! -e $work/bad.json ]] || fail "$* -> left an output file"
}

expect_error --count --near 15 --count 0
expect_error --count --near 15 --count -2
expect_error --count --near 15 --count 101
expect_error --near --near -1 --count 3
expect_error --near --near 15
expect_error --count --count 3
expect_error --window --window 30:20
expect_error --window --window abc
expect_error --window --window 10:20 --near 15 --count 3
expect_error --method --near 15 --count 3 --method magma
expect_error --count --near 15 --count 100 --method arpack

for method in $methods; do
  # above the spectrum: the K highest modes
  "$tool" --N 100 --quiet --near 1000 --count 4 --method $method --output "$work/top.csv" || fail "$method top"
  [[ $(tail -n +2 "$work/top.csv" | cut -d, -f1 | tr '\n' ' ') == "97 98 99 100 " ]] || fail "$method top modes: $(cat "$work/top.csv")"
  # a window with no modes: header only, exit 0
  "$tool" --N 100 --quiet --window 100:200 --method $method --output "$work/empty.csv" || fail "$method empty"
  [[ $(cat "$work/empty.csv") == "mode,freq_khz,ipr" ]] || fail "$method empty window: $(cat "$work/empty.csv")"
  [[ -s $work/empty.json ]] || fail "$method empty window wrote no JSON"
done
# K = N with LAPACK: the whole spectrum
"$tool" --N 100 --quiet --near 15 --count 100 --output "$work/all.csv" || fail "K = N"
[[ $(tail -n +2 "$work/all.csv" | wc -l) -eq 100 ]] || fail "K = N rows"
# eigenvectors to HDF5
"$tool" --N 100 --quiet --near 15 --count 3 --vectors "$work/v.h5" --output "$work/v.csv" || fail "vectors"
[[ -s $work/v.h5 ]] || fail "no HDF5 file"
echo "partial-spectrum CLI contract holds"
