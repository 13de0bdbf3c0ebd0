#pragma once
// Shared by the breather tests: how far a computed breather is from periodic under direct integration.
#include <cmath>
#include <cstddef>
#include <numbers>

#include "granular/dynamics/propagator.hpp"
#include "granular/study/breather_branch.hpp"

namespace granular::fixtures {

/// ‖(u − x0, u̇/ω_b)‖/‖x0‖ after `periods` periods of direct integration (SABA2C, `steps` per
/// period) from the breather's turning state (x0, 0).
inline double state_error_after(const Chain& chain, const BreatherPoint& p, std::size_t steps, std::size_t periods) {
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  State start(chain.size());
  start.u = p.x0;
  const double tau = 2 * std::numbers::pi / p.omega / static_cast<double>(steps);
  auto prop = make_splitting_propagator(law, chain, saba2c(), tau, start, {.enabled = false});
  prop->advance(periods * steps);
  double err = 0, norm = 0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    err += std::pow(prop->displacement()[i] - p.x0[i], 2) + std::pow(prop->velocity()[i] / p.omega, 2);
    norm += p.x0[i] * p.x0[i];
  }
  return std::sqrt(err / norm);
}

}  // namespace granular::fixtures
