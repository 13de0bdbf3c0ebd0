#!/usr/bin/env bash
# The install test (ctest label `install`): installs this build tree into a scratch prefix and
# uses it as an outside project would, compiled WITHOUT -march=native (the library is built
# with it): examples/ through find_package(granular), and a one-file program through
# pkg-config. Fails on the first step that does not work, naming it.
# Usage: check-install.sh SOURCE_DIR BUILD_DIR WORK_DIR CMAKE CTEST CXX PKG_CONFIG
set -euo pipefail
src=$1 build=$2 work=$3 cmake=$4 ctest=$5 cxx=$6 pkg_config=$7
prefix=$work/prefix
fail() { echo "install test: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
"$cmake" --install "$build" --prefix "$prefix" >"$work/install.log" || fail "cmake --install failed (see $work/install.log)"
libdir=$(dirname "$(find "$prefix" -name 'libgranular.*' -print -quit)")
[ -d "$libdir" ] || fail "no libgranular installed"

# What must be there, and what must not.
for f in include/granular/granular.hpp include/granular/error.hpp include/granular/linear/spectrum.hpp \
         include/granular/model/chain.hpp share/doc/granular/physics.md bin/spectrum \
         share/granular/plot/spectrum.py; do
  [ -e "$prefix/$f" ] || fail "missing $f"
done
# Every doc the README links is installed beside it, at the same relative path.
for link in $(grep -o '](docs/[^)#]*' "$src/README.md" | sed 's/^](//' | sort -u); do
  [ -e "$prefix/share/doc/granular/$link" ] || fail "the README links $link, not installed beside it"
done
[ -z "$(find "$prefix/include" -type d -name detail)" ] || fail "a detail/ folder was installed"
[ -f "$libdir/cmake/granular/granularConfig.cmake" ] || fail "missing granularConfig.cmake"
[ -f "$libdir/cmake/granular/granularConfigVersion.cmake" ] || fail "missing granularConfigVersion.cmake"
[ -f "$libdir/pkgconfig/granular.pc" ] || fail "missing granular.pc"
# Build-only settings must not reach consumers: no -march, no source paths, no build macros.
if grep -rn -e '-march=' -e "$src" -e "$build" "$libdir/cmake/granular" "$libdir/pkgconfig/granular.pc"; then
  fail "the exported interface carries a build-only flag or path (above)"
fi
if grep -rln -e 'GRANULAR_HAVE_' -e 'GRANULAR_SOURCE_DIR' -e 'GRANULAR_VERSION' "$prefix/include"; then
  fail "an installed header uses a macro only the in-tree build defines (files above)"
fi
# `man spectrum` works from the prefix (MANPATH), and the page is the tool's --help.
if command -v man >/dev/null && command -v help2man >/dev/null; then
  page=$(MANPATH=$prefix/share/man man -w spectrum) || fail "man -w spectrum finds no page under $prefix/share/man"
  [ "$page" = "$prefix/share/man/man1/spectrum.1" ] || fail "man spectrum resolves to $page"
  MANPATH=$prefix/share/man MANWIDTH=100 man spectrum 2>/dev/null | grep -q -e '--near' || fail "man spectrum lacks --near"
fi
# The installed tools find the installed library.
"$prefix/bin/spectrum" --version >/dev/null || fail "installed bin/spectrum does not run"
# The components load from beside the installed library, when a run needs them.
[ -e "$libdir/libgranular_hdf5.so" ] || fail "missing libgranular_hdf5.so beside libgranular"
"$prefix/bin/spectrum" --N 30 --quiet --near 15 --count 3 --vectors "$work/v.h5" --output "$work/v" \
  || fail "installed spectrum --vectors (the HDF5 component) failed"
components=hdf5
if [ -e "$libdir/libgranular_slepc.so" ]; then
  "$prefix/bin/spectrum" --N 30 --quiet --near 15 --count 3 --method slepc --output "$work/s" \
    || fail "installed spectrum --method slepc (the SLEPc component) failed"
  components="hdf5 slepc"
fi
# find_package(granular COMPONENTS ...) finds the installed ones and refuses an unknown one.
mkdir -p "$work/components"
printf 'cmake_minimum_required(VERSION 3.22)\nproject(c LANGUAGES CXX)\nfind_package(granular REQUIRED COMPONENTS %s)\n' \
  "$components" >"$work/components/CMakeLists.txt"
"$cmake" -S "$work/components" -B "$work/components/build" -DCMAKE_PREFIX_PATH="$prefix" >"$work/components.log" 2>&1 \
  || { cat "$work/components.log"; fail "find_package(granular COMPONENTS $components) failed"; }
sed -i "s/COMPONENTS .*)/COMPONENTS nosuch)/" "$work/components/CMakeLists.txt"
"$cmake" -S "$work/components" -B "$work/components/build2" -DCMAKE_PREFIX_PATH="$prefix" >"$work/components.log" 2>&1 \
  && fail "find_package(granular COMPONENTS nosuch) succeeded"

# The Python package where docs/python.md says: lib/python3.X/dist-packages of the prefix, and it
# imports from outside the source and build trees.
core=$(find "$prefix" -name '_core*.so' -print -quit)
if [ -n "$core" ]; then
  pydir=$(dirname "$(dirname "$core")")
  case "$pydir" in "$prefix"/lib/python3.*/dist-packages) ;; *) fail "Python package installed in $pydir" ;; esac
  (cd / && PYTHONPATH=$pydir /usr/bin/python3 -c "import granular; assert granular.__file__.startswith('$pydir'); \
    assert len(granular.spectrum(granular.anderson(N=20)).freq_khz) == 20") || fail "the installed granular does not import"
fi

# 1. examples/ as a downstream CMake project: configure, build, run every example.
"$cmake" -S "$src/examples" -B "$work/examples" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >"$work/examples-configure.log" 2>&1 \
  || { cat "$work/examples-configure.log"; fail "configuring examples/ against the install failed"; }
"$cmake" --build "$work/examples" -j2 >"$work/examples-build.log" 2>&1 \
  || { cat "$work/examples-build.log"; fail "building examples/ against the install failed"; }
if grep -n -e '-march=' "$work/examples/compile_commands.json"; then fail "examples were compiled with -march"; fi
grep -q -- '-ffp-contract=off' "$work/examples/compile_commands.json" || fail "granular::granular does not carry -ffp-contract=off"
grep -q -- "-I$src" "$work/examples/compile_commands.json" && fail "examples see the source tree's headers"
"$ctest" --test-dir "$work/examples" --output-on-failure || fail "an example failed its check"

# 2. pkg-config: one file that includes every installed header and calls the library.
export PKG_CONFIG_PATH=$libdir/pkgconfig
flags=$("$pkg_config" --cflags --libs granular) || fail "pkg-config --cflags --libs granular failed"
echo "pkg-config --cflags --libs granular: $flags"
{
  (cd "$prefix/include" && find granular -name '*.hpp' | sort | sed 's/.*/#include <&>/')
  cat <<'CPP'
#include <cstdio>
#include <vector>
int main() {  // every installed header compiles on its own include path, and the library links
  const auto chain = granular::from_radii(std::vector<double>(30, 4.76e-3), 10.0);
  const auto modes = granular::spectrum(granular::dynamical_matrix(chain), granular::all_modes(), {.vectors = true});
  std::printf("pkg-config program: %zu modes, highest %.6f kHz\n", modes.size(), modes.freq_khz.back());
  return modes.size() == 30 && modes.vectors.size() == 30 * 30 ? 0 : 1;
}
CPP
} >"$work/pc_program.cpp"
# shellcheck disable=SC2086  # $flags is a list of words
"$cxx" -std=c++20 -O2 "$work/pc_program.cpp" -o "$work/pc_program" $flags || fail "compiling with pkg-config flags failed"
LD_LIBRARY_PATH=$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} "$work/pc_program" || fail "the pkg-config program failed"
echo "install test: installed, found by find_package and pkg-config, examples pass"
