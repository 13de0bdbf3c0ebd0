#include "granular/dynamics/restitution.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/error.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

void validate(const CollisionConfig& c) {
  if (!std::isfinite(c.impact_speed) || !(c.impact_speed > 0))
    throw InvalidInput("impact_speed", " " + format_number(c.impact_speed) + ": must be finite and > 0");
  if (!std::isfinite(c.radius) || !(c.radius > 0))
    throw InvalidInput("radius", " " + format_number(c.radius) + ": must be finite and > 0");
  if (!std::isfinite(c.steps_per_collision) || !(c.steps_per_collision >= 10))
    throw InvalidInput("steps_per_collision", " " + format_number(c.steps_per_collision) + ": must be >= 10");
  validate(Damping{0, c.kk_gamma});
}

// Two beads joined by one Hertz bond; the wall bonds have A = 0, so the walls exert nothing.
Chain two_beads(const CollisionConfig& c) {
  Chain chain;
  const double mass = c.material.density * 4.0 / 3.0 * std::numbers::pi * c.radius * c.radius * c.radius;
  chain.radius = {c.radius, c.radius};
  chain.mass = {mass, mass};
  chain.inverse_mass = {1 / mass, 1 / mass};
  chain.contact = {0, hertz_coefficient(c.material, c.radius, c.material, c.radius), 0};
  chain.overlap = {0, 0, 0};
  chain.precompression = 0;
  return chain;
}

}  // namespace

double hertz_contact_time(const CollisionConfig& c) {
  validate(c);
  const Chain chain = two_beads(c);
  const double mu = chain.mass[0] / 2, a = chain.contact[1], v = c.impact_speed;
  const double max_overlap = std::pow(5 * mu * v * v / (4 * a), 0.4);
  const double integral = 0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);  // ∫₀¹ (1 − x^{5/2})^{−1/2}
  return 2 * max_overlap / v * integral;
}

double restitution_deficit_small_damping(const CollisionConfig& c) {
  validate(c);
  const Chain chain = two_beads(c);
  const double mu = chain.mass[0] / 2;
  return 1.15344 * c.kk_gamma * std::pow(chain.contact[1] / mu, 0.4) * std::pow(c.impact_speed, 0.2);
}

Collision two_bead_collision(const CollisionConfig& c) {
  validate(c);
  const Chain chain = two_beads(c);
  Collision r;
  r.hertz_time = hertz_contact_time(c);
  r.time_step = r.hertz_time / c.steps_per_collision;
  State s0(2);
  s0.v[0] = c.impact_speed;
  r.initial_energy = 0.5 * chain.mass[0] * c.impact_speed * c.impact_speed;
  const ForceLaw law = make_force_law(ForceLawKind::hertz, chain);
  auto p = make_damped_propagator(law, chain, parse_scheme(c.integrator, "integrator"), r.time_step, s0,
                                  Damping{0, c.kk_gamma});
  const auto limit = static_cast<std::uint64_t>(20 * c.steps_per_collision);
  bool touched = false;
  while (p->steps_done() < limit) {
    p->advance(1);
    const auto u = p->displacement();
    const auto v = p->velocity();
    const double overlap = u[0] - u[1];
    r.max_overlap = std::max(r.max_overlap, overlap);
    touched = touched || overlap > 0;
    // Open and separating: no force acts any more, the velocities are final.
    if (touched && overlap < 0 && v[0] < v[1]) {
      r.restitution = (v[1] - v[0]) / c.impact_speed;
      r.contact_time = p->time();
      r.dissipated = p->dissipated_energy();
      return r;
    }
  }
  throw NumericalError("two-bead collision: the contact did not open within 20 contact times");
}

}  // namespace granular
