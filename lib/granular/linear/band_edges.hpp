#pragma once
// Analytic cut-off frequencies of ordered chains (docs/physics.md, "Band edges").
#include "granular/model/material.hpp"

namespace granular {

struct BandEdges {
  double f1;   ///< top of the monatomic chain of type-1 beads [Hz]
  double f2;   ///< top of the monatomic chain of type-2 beads [Hz]
  double fb1;  ///< diatomic (1,2,1,2…) acoustic band top, sqrt(2 B12 / m1)/2π [Hz]
  double fb2;  ///< diatomic optical band bottom, sqrt(2 B12 / m2)/2π [Hz]
  double fb3;  ///< diatomic optical band top, sqrt(2 B12 / m3)/2π, m3 = m1 m2/(m1+m2) [Hz]
};

/// Band edges for beads of radius r1 and ξ r1 of one material under precompression F0 > 0.
BandEdges band_edges(const Material& material, double r1, double xi, double precompression);

}  // namespace granular
