#!/usr/bin/env bash
# SLEPc under mpirun -np 2 (rows split over two ranks) agrees with -np 1, and with LAPACK.
# usage: partial_spectrum_mpi.sh MPIEXEC TOOL PYTHON WORKDIR
set -euo pipefail
mpiexec=$1 tool=$2 python=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
common=(--disorder A --N 20000 --near 15 --count 16 --quiet)
"$mpiexec" --oversubscribe -np 1 "$tool" "${common[@]}" --method slepc --output "$work/np1.csv"
"$mpiexec" --oversubscribe -np 2 "$tool" "${common[@]}" --method slepc --output "$work/np2.csv"
"$tool" "${common[@]}" --method lapack --output "$work/lapack.csv"
grep -q '"mpi_ranks": 2' "$work/np2.json" || { echo "np2 run did not see 2 ranks"; exit 1; }
"$python" "$here/compare_partial_spectra.py" "$work/np1.csv" "$work/np2.csv" 16
"$python" "$here/compare_partial_spectra.py" "$work/lapack.csv" "$work/np2.csv" 16
