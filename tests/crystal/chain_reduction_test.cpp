// A square crystal with walls whose transverse coupling (the prestress term) is removed is a set of
// independent 1D chains: its rows move in x, its columns in y, each the 1D toolkit's chain with the
// same beads, walls and F0 (docs/crystals.md, "The dynamical matrix").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "granular/crystal/crystal_matrix.hpp"
#include "granular/crystal/crystal_spectrum.hpp"
#include "granular/crystal/static_state.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/chain.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

// ω² of the 1D chain made of the given beads of packing p, between flat walls of their materials.
std::vector<double> chain_omega2(const Packing& p, const std::vector<std::size_t>& beads) {
  ChainSpec spec;
  for (std::size_t b : beads) spec.radii.push_back(p.radius[b]), spec.materials.push_back(p.material[b]);
  spec.precompression = p.precompression;
  return spectrum(dynamical_matrix(make_chain(spec))).omega2;
}

TEST(ChainReduction, SquareWithoutPrestressIsRowsAndColumnsOfTheChainAt1e12) {
  PackingSpec spec;
  spec.Lx = 7, spec.Ly = 5, spec.precompression = 10;
  // Mass disorder keeps every contact's A and the static state, and makes each row a different chain.
  const Packing p = make_packing(disordered(spec, {.kind = PackingDisorder::Kind::mass, .width = 0.3, .seed = 4}));
  const StaticState state = static_state(p);
  const CrystalSpectrum crystal = crystal_spectrum(crystal_matrix(p, state, {.prestress = false}));

  std::vector<double> chains;
  const auto Lx = static_cast<std::size_t>(spec.Lx), Ly = static_cast<std::size_t>(spec.Ly);
  for (std::size_t j = 0; j < Ly; ++j) {
    std::vector<std::size_t> row;
    for (std::size_t i = 0; i < Lx; ++i) row.push_back(j * Lx + i);
    for (double w : chain_omega2(p, row)) chains.push_back(w);
  }
  for (std::size_t i = 0; i < Lx; ++i) {
    std::vector<std::size_t> column;
    for (std::size_t j = 0; j < Ly; ++j) column.push_back(j * Lx + i);
    for (double w : chain_omega2(p, column)) chains.push_back(w);
  }
  std::sort(chains.begin(), chains.end());
  ASSERT_EQ(chains.size(), crystal.size());
  double worst = 0;
  for (std::size_t k = 0; k < chains.size(); ++k)
    worst = std::max(worst, std::fabs(std::sqrt(crystal.omega2[k]) - std::sqrt(chains[k])) / std::sqrt(chains[k]));
  RecordProperty("worst_relative_difference", format_number(worst));
  EXPECT_LT(worst, 1e-12) << "worst relative frequency difference";

  // With the prestress term the crystal is softer: the rows' transverse stiffness −f/d.
  const CrystalSpectrum coupled = crystal_spectrum(crystal_matrix(p, state));
  double trace_free = 0, trace_coupled = 0;
  for (std::size_t k = 0; k < chains.size(); ++k) trace_free += crystal.omega2[k], trace_coupled += coupled.omega2[k];
  EXPECT_LT(trace_coupled, trace_free);
}

}  // namespace
}  // namespace granular
