#pragma once
// Batches of chains for the lane propagators' tests (lane_propagator_test.cpp,
// lane_tangent_propagator_test.cpp): chains of one length, their laws and starts.
#include <cmath>
#include <cstddef>
#include <vector>

#include "dynamics/dynamics_fixtures.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/state.hpp"
#include "granular/klein_gordon/klein_gordon.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/material.hpp"
#include "granular/model/quasiperiodic.hpp"

namespace granular::fixtures {

struct Batch {
  std::vector<Chain> chains;
  std::vector<State> initials;
  std::vector<ForceLaw> laws;
};

/// Up to `count` Anderson chains of n beads, kicked at sites spread over the chain (so their windows
/// open apart), the last lane over the whole chain when `one_spread`.
inline Batch granular_batch(std::size_t count, std::size_t n, double f0, ForceLawKind kind, bool one_spread,
                            std::size_t site_step = 37) {
  Batch b;
  for (std::size_t l = 0; l < count; ++l) {
    b.chains.push_back(fixtures::anderson(n, f0, l));
    const std::size_t site = (l * site_step + n / 3) % n;
    if (one_spread && l + 1 == count) {  // every bead displaced: the window is the whole chain
      std::vector<double> shape(n);
      for (std::size_t i = 0; i < n; ++i) shape[i] = std::sin(0.3 * static_cast<double>(i + 1));
      b.initials.push_back(shaped_displacement(b.chains.back(), shape, 1e-8));
    } else {
      b.initials.push_back(velocity_kick(b.chains.back(), site, 0.01 * static_cast<double>(l + 1)));
    }
    b.laws.push_back(make_force_law(kind, b.chains.back()));
  }
  return b;
}

/// `count` S1 quasiperiodic chains (Hertz bonds, linear on-site springs), phases 0.1 l apart.
inline Batch s1_batch(std::size_t count) {
  Batch b;
  for (std::size_t l = 0; l < count; ++l) {
    const Quasiperiodic q{.kind = Quasiperiodic::Kind::s1, .modulation = 0.7, .phase = 0.1 * static_cast<double>(l)};
    b.chains.push_back(quasiperiodic_chain(q, 150, fixtures::r1, 10.0, steel, 0.4));
    b.initials.push_back(velocity_kick(b.chains.back(), 40 + 9 * l, 0.02));
    b.laws.push_back(make_force_law(ForceLawKind::hertz, b.chains.back()));
  }
  return b;
}

/// `count` realizations of a disordered Klein-Gordon chain (linear bonds, quartic on-site springs).
inline Batch klein_gordon_batch(std::size_t count) {
  Batch b;
  for (std::size_t l = 0; l < count; ++l) {
    b.chains.push_back(klein_gordon({.N = 120, .W = 4, .seed = 3, .realization = l}));
    b.initials.push_back(site_energy_kick(b.chains.back(), 30 + 7 * l, 0.4));
    b.laws.push_back(make_force_law(ForceLawKind::linear, b.chains.back()));
  }
  return b;
}

}  // namespace granular::fixtures
