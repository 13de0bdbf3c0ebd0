#!/usr/bin/env bash
# Runs `spreading` on the paper's set-ups (one realization each) and draws the spreading figures.
# Usage: tools/plot/make_spreading_figures.sh BUILD_DIR OUTPUT_DIR   (about 15 s on 2 cores)
set -euo pipefail
build=$(realpath "${1:-build}")
out=${2:-figures}
here=$(dirname "$(realpath "$0")")
mkdir -p "$out"
cd "$out"
spreading="$build/spreading"
plot="/usr/bin/python3 $here/spreading_figures.py"

# Spatiotemporal energy map beside the spectral density: N = 1601, kick at 801 (docs/physics.md, "Nonlinear dynamics").
$spreading --disorder A --N 1601 --F0 10 --output map-A --energy-map map-A.h5 --map-samples 400 \
  --spectrum spectrum-A.csv --spectrum-samples 2000 --quiet
$plot map map-A.h5 spectrum-A.csv -o map-A.png

# Force versus time at beads 601, 631, 661 of N = 1201 (Anderson, xi = 0.8) beside the force profile at T.
$spreading --disorder A --xi 0.8 --N 1201 --F0 0.5 --output forces-A --forces-at 601,631,661 --force-samples 5000 --profile --quiet
$plot forces forces-A-forces.csv forces-A-profile.csv -o forces-A.png

# m2(t) and P^-1(t) for the four disorders, N = 2501, F0 = 10 N.
for d in h A RDM1 RDM2; do
  $spreading --disorder $d --N 2501 --F0 10 --output spread-$d --quiet
done
$plot spread spread-h.csv spread-A.csv spread-RDM1.csv spread-RDM2.csv --labels h,A,RDM1,RDM2 -o spread.png
# The spectral density of one sonic-vacuum run (Anderson, velocity kick 8e-3 m/s, N = 2501) and of the
# same kick at F0 = 10 N, each of the displacements (the paper's g) and of the velocities.
for f0 in 0 10; do
  for of in displacement velocity; do
    $spreading --disorder A --N 2501 --F0 $f0 --ic velocity --output run-F$f0-$of --spectrum g-F$f0-$of.csv \
      --spectrum-samples 2000 --spectrum-of $of --quiet
  done
done
$plot spectra g-F0-displacement.csv g-F0-velocity.csv g-F10-displacement.csv g-F10-velocity.csv \
  --titles "A, F0 = 0 (sonic vacuum), velocity kick;A, F0 = 10 N, velocity kick" -o spectral-density.png
echo "figures in $(pwd): map-A.png forces-A.png spread.png spectral-density.png"
