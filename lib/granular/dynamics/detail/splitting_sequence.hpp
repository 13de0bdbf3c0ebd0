#pragma once
// The order in which a splitting scheme's stages run over whole steps (docs/physics.md, "Nonlinear
// dynamics"), written once for every stepper that follows it (the one-chain stepper, the tangent
// map, the lanes): each drift is fused into the kick or corrector before it, the last drift of a
// step merges with the first of the next when the scheme has no corrector, and the end corrector of
// a step merges with the start corrector of the next (2 g τ³, g the scheme's corrector weight).
#include <cstddef>

#include "granular/dynamics/scheme.hpp"

namespace granular::detail {

/// Runs `steps` (≥ 1) steps of `scheme` at τ = `tau`: kick(h, d) is v += h F/m then u += d v;
/// correct(c, d) the corrector with weight c, then u += d v; drift(d) u += d v alone; end_of_step()
/// after every step.
template <class Kick, class Correct, class Drift, class EndOfStep>
void splitting_sequence(const SplittingScheme& scheme, double tau, std::size_t steps, Kick&& kick, Correct&& correct,
                        Drift&& drift, EndOfStep&& end_of_step) {
  const double g = scheme.corrector * tau * tau * tau;
  const auto& a = scheme.drift;
  const auto& b = scheme.kick;
  const std::size_t last = b.size() - 1;
  if (g != 0) correct(g, a[0] * tau);
  else drift(a[0] * tau);
  for (std::size_t step = 0; step < steps; ++step) {
    const bool more = step + 1 < steps;
    for (std::size_t j = 0; j <= last; ++j) {
      double after = a[j + 1] * tau;
      if (j == last && g == 0 && more) after += a[0] * tau;
      kick(b[j] * tau, after);
    }
    if (g != 0) correct(more ? 2 * g : g, more ? a[0] * tau : 0.0);
    end_of_step();
  }
}

}  // namespace granular::detail
