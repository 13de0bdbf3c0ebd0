#!/usr/bin/env bash
# Installs the Debian 12 packages the toolkit builds, tests and plots with.
# Idempotent: when every package is already there it changes nothing and takes a second.
# Works as root or through sudo.
#
# BLAS: the build links Debian's libblas.so.3 / liblapack.so.3, and libopenblas0-pthread makes
# update-alternatives point both at OpenBLAS (priority 100 over the reference BLAS's 10), the
# library anyone who cares about speed runs NumPy, SciPy and LAPACK on. The reference BLAS stays
# installed (libblas3, liblapack3, named here because the tests use their folders
# /usr/lib/x86_64-linux-gnu/blas and …/lapack): tests/run-all.sh runs the linear-algebra suites on
# it too (LD_LIBRARY_PATH; pass 1b, and the ctest tests reference_blas.* in pass 1), and
# `TOOL --version` or any run's JSON ("blas") says which one a process used.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git time help2man man-db
  libeigen3-dev liblapack-dev libblas-dev libblas3 liblapack3 libopenblas0-pthread libarpack2-dev libsuitesparse-dev
  libfftw3-dev libhdf5-dev libboost-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev librandom123-dev
  openmpi-bin libopenmpi-dev petsc-dev slepc-dev
  python3 python3-venv python3-numpy python3-scipy python3-threadpoolctl python3-matplotlib python3-h5py
  pybind11-dev python3-pybind11 python3-pytest jupyter-nbconvert python3-nbformat python3-ipykernel
  clang libclang-rt-14-dev libomp-14-dev clang-format
  python3-sphinx python3-myst-parser python3-breathe python3-nbsphinx python3-sphinx-rtd-theme doxygen pandoc chromium
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
