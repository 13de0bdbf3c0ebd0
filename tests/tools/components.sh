#!/usr/bin/env bash
# A tool pays only for what it uses (docs/performance.md, start-up): no tool and not the Python
# module links PETSc, SLEPc, HDF5 or MPI (ldd lists every library loaded at start-up,
# recursively); a run loads them only when it uses the SLEPc method, writes HDF5 or runs under
# mpirun; and without its component such a run fails with one line naming the missing file,
# leaving no output.
# usage: components.sh BUILD_DIR WORKDIR PYTHON_MODULE|- TOOL...
set -uo pipefail
build=$1 work=$2 module=$3
shift 3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
heavy='lib(petsc|slepc|hdf5|mpi)[._]'

for file in "$@" $([[ $module != - ]] && echo "$module"); do
  linked=$(ldd "$file") || fail "ldd $file"
  if grep -E "$heavy" <<<"$linked"; then fail "$(basename "$file") loads the libraries above at start-up"; fi
  echo "$(basename "$file"): $(wc -l <<<"$linked") libraries at start-up"
done

# loaded_by NAME CMD...: the libraries matching NAME the dynamic linker loaded for the run.
loaded_by() {
  local name=$1; shift
  LD_DEBUG=files LD_DEBUG_OUTPUT="$work/ld" "$@" >/dev/null 2>&1 || fail "$* failed"
  cat "$work"/ld.* | grep -oE "file=[^ ]*$name[^ ]*" | sort -u
  rm -f "$work"/ld.*
}
spectrum=$build/spectrum spreading=$build/spreading
[[ -z $(loaded_by "$heavy" "$spectrum" --N 50 --quiet --output "$work/a.csv") ]] || fail "spectrum loads PETSc/HDF5/MPI"
[[ -n $(loaded_by hdf5 "$spectrum" --N 50 --quiet --near 15 --count 3 --vectors "$work/v.h5" --output "$work/v.csv") ]] ||
  fail "spectrum --vectors does not load HDF5"
if [[ -e $build/libgranular_slepc.so ]]; then
  [[ -n $(loaded_by petsc "$spectrum" --N 50 --quiet --near 15 --count 3 --method slepc --output "$work/s.csv") ]] ||
    fail "spectrum --method slepc does not load PETSc"
fi
run=(--N 51 --T 1e-4 --samples 5 --quiet)
[[ -z $(loaded_by "$heavy" "$spreading" "${run[@]}" --output "$work/plain") ]] || fail "spreading loads PETSc/HDF5/MPI"
[[ -n $(loaded_by hdf5 "$spreading" "${run[@]}" --energy-map "$work/map.h5" --map-samples 5 --output "$work/map") ]] ||
  fail "spreading --energy-map does not load HDF5"

# A missing component: exit 1 (a file could not be used), one line naming it, no output.
expect_missing() {  # expect_missing FILE OUTPUT-STEM CMD...
  local file=$1 stem=$2; shift 2
  local err code
  err=$(GRANULAR_COMPONENT_DIR=$work/nowhere "$@" 2>&1 >/dev/null)
  code=$?
  [[ $code -eq 1 ]] || fail "$* without $file -> exit $code (want 1): $err"
  [[ $(printf '%s\n' "$err" | wc -l) -eq 1 ]] || fail "$* without $file -> message not one line: $err"
  [[ $err == *"$file"* ]] || fail "$* without $file -> message does not name it: $err"
  [[ -z $(compgen -G "$stem*") ]] || fail "$* without $file -> left $(compgen -G "$stem*")"
}
expect_missing libgranular_hdf5.so "$work/miss" "$spectrum" --N 50 --quiet --near 15 --count 3 \
  --vectors "$work/miss.h5" --output "$work/miss"
expect_missing libgranular_hdf5.so "$work/missmap" "$spreading" "${run[@]}" --energy-map "$work/missmap.h5" \
  --map-samples 5 --output "$work/missmap"
# breathers always writes its profiles (.h5): without the component it fails before its first
# point, which would print a progress line (not --quiet here).
expect_missing libgranular_hdf5.so "$work/missbr" "$build/breathers" --quasi s1 --modulation 0 --phase 0 \
  --k0-n-per-m 1e7 --F0 0 --N 21 --max-points 2 --output "$work/missbr"
err=$(GRANULAR_COMPONENT_DIR=$work/nowhere "$build/breathers" --quasi s1 --modulation 0 --phase 0 --k0-n-per-m 1e7 \
  --F0 0 --N 21 --max-points 2 --output "$work/missbr" 2>&1 >/dev/null)
[[ $err != *kHz* ]] || fail "breathers without libgranular_hdf5.so computed points first: $err"
# GRANULAR_COMPONENT_DIR must be absolute: a relative path to the right folder is refused (it would
# load code from wherever the run starts), exit 1 naming the variable, nothing written.
relative=$(realpath --relative-to="$work" "$build")
err=$(cd "$work" && GRANULAR_COMPONENT_DIR=$relative "$spectrum" --N 50 --quiet --near 15 --count 3 \
  --vectors "$work/rel.h5" --output "$work/rel" 2>&1 >/dev/null)
code=$?
[[ $code -eq 1 && $err == *GRANULAR_COMPONENT_DIR*absolute* ]] ||
  fail "a relative GRANULAR_COMPONENT_DIR=$relative -> exit $code: $err"
[[ -z $(compgen -G "$work/rel*") ]] || fail "a relative GRANULAR_COMPONENT_DIR left $(compgen -G "$work/rel*")"
if [[ -e $build/libgranular_slepc.so ]]; then
  expect_missing libgranular_slepc.so "$work/nos" "$spectrum" --N 50 --quiet --near 15 --count 3 --method slepc \
    --output "$work/nos"
fi
echo "each tool loads PETSc/SLEPc, HDF5 and MPI only when a run uses them"
