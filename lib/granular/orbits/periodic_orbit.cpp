#include "granular/orbits/periodic_orbit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include "granular/detail/enum_names.hpp"
#include "granular/detail/euclidean_norm.hpp"
#include "granular/dynamics/detail/dense_lapack.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"
#include "granular/orbits/detail/shooting_krylov.hpp"

namespace granular {
namespace {

using detail::euclidean_norm;
constexpr double inf = std::numeric_limits<double>::infinity();

void check_frequency(double omega) {
  if (!(omega > 0) || !std::isfinite(omega)) throw InvalidInput("omega", ": the frequency must be finite and > 0");
}

void check_dense(std::size_t n, const ShootingConfig& config) {
  if (n > config.max_dense_beads)
    throw InvalidInput("N", " " + std::to_string(n) + ": more beads than the dense shooting Jacobian allows (" +
                                std::to_string(config.max_dense_beads) + ")");
}

constexpr auto newton_method_names = detail::enum_names<NewtonMethod>("newton", {{NewtonMethod::automatic, "auto"},
                                                                                 {NewtonMethod::dense, "dense"},
                                                                                 {NewtonMethod::krylov, "krylov"}});

std::string khz(double omega) { return format_number(omega / (2 * std::numbers::pi) / 1e3); }

}  // namespace

NewtonMethod parse_newton_method(const std::string& name) { return newton_method_names.parse(name); }
std::string to_string(NewtonMethod method) { return std::string(newton_method_names.name_of(method)); }

bool uses_newton_krylov(std::size_t beads, const ShootingConfig& config) {
  if (config.newton == NewtonMethod::krylov) return true;
  if (config.newton == NewtonMethod::dense) check_dense(beads, config);
  return beads > config.max_dense_beads;
}

std::size_t shooting_steps(const Chain& chain, double omega) {
  check_frequency(omega);
  // Gershgorin on M^{-1} K: every eigenvalue ω² ≤ max_i (2 (B_i + B_{i+1}) + k_i) / m_i, with
  // the on-site springs k_i (none: 0; at F0 = 0 they are all the linear stiffness there is).
  double omega_max = omega;
  const auto b = chain.precompression > 0 || !chain.spring.empty() ? linear_stiffness(chain)
                                                                   : std::vector<double>(chain.bonds(), 0.0);
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const double k = chain.onsite.empty() ? 0.0 : chain.onsite[i];
    omega_max = std::max(omega_max, std::sqrt((2 * (b[i] + b[i + 1]) + k) * chain.inverse_mass[i]));
  }
  const double steps = std::ceil(2 * std::numbers::pi * omega_max / (omega * 0.05));
  auto n = static_cast<std::size_t>(std::max(128.0, std::min(steps, 1e7)));
  return n + n % 2;
}

HalfPeriodMap half_period_map(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                              std::size_t steps_per_period, double omega, const std::vector<double>& x0, bool jacobian) {
  check_frequency(omega);
  const std::size_t n = chain.size();
  if (x0.size() != n) throw InvalidInput("guess", ": must have one displacement per bead");
  if (steps_per_period < 2 || steps_per_period % 2 != 0)
    throw InvalidInput("steps_per_period", " " + std::to_string(steps_per_period) + ": must be even and >= 2");
  const double tau = 2 * std::numbers::pi / omega / static_cast<double>(steps_per_period);
  State start(n);
  start.u = x0;
  std::vector<State> columns;
  if (jacobian) {
    columns.assign(n, State(n));
    for (std::size_t j = 0; j < n; ++j) columns[j].u[j] = 1;
  }
  const auto images = propagate_deviations(law, chain, scheme, tau, steps_per_period / 2, start, columns);
  HalfPeriodMap out;
  out.velocity = images.orbit.v;
  if (jacobian) {
    out.jacobian.resize(n * n);
    for (std::size_t j = 0; j < n; ++j)
      std::copy(images.deviations[j].v.begin(), images.deviations[j].v.end(), out.jacobian.begin() + j * n);
  }
  for (double v : out.velocity)
    if (!std::isfinite(v)) throw NumericalError("shooting: the orbit became non-finite");
  return out;
}

double relative_residual(const std::vector<double>& velocity, double omega, const std::vector<double>& x0) {
  const double scale = omega * euclidean_norm(x0);
  return scale > 0 ? euclidean_norm(velocity) / scale : inf;
}

namespace {

// The unknowns of a shooting problem: the turning-point displacements x0 [m] and ω_b [rad/s].
struct ShootingPoint {
  std::vector<double> x;
  double omega = 0;
};

// How far a point is from an orbit: the relative residual of u̇(T/2) and, on an arc, the
// arclength condition (0 at fixed frequency); with u̇(T/2) itself, which a matrix-free Newton step
// at that point needs again (a half-period integration spared per step).
struct ShootingMisfit {
  double residual = 0;
  double arc = 0;
  std::vector<double> velocity{};
  [[nodiscard]] double merit() const { return std::hypot(residual, arc); }
  [[nodiscard]] bool within(double tolerance) const { return residual <= tolerance && std::abs(arc) <= tolerance; }
};

// How the messages name the method and place the frequency: {"Newton", "at"}.
struct NewtonWords {
  std::string method;
  std::string where;
};

// The damped Newton iteration both problems share: newton_step(z, misfit at z) linearizes at z and
// returns the full correction, misfit(z) measures a trial; a step is halved (up to 10 times) until the merit
// falls, and an iterate that shrinks to the rest state is refused (zero is always an orbit).
template <class NewtonStep, class Misfit>
PeriodicOrbit damped_newton(ShootingPoint z, const NewtonWords& words, const ShootingConfig& config,
                            std::size_t steps_per_period, NewtonStep newton_step, Misfit misfit) {
  const double guess_norm = euclidean_norm(z.x);
  if (!(guess_norm > 0) || !std::isfinite(guess_norm))
    throw InvalidInput("guess", ": must be finite and not all zero (zero is the trivial orbit)");
  const auto at = [&] { return " " + words.where + " " + khz(z.omega) + " kHz"; };
  PeriodicOrbit orbit;
  orbit.scheme = config.scheme;
  orbit.steps_per_period = steps_per_period;
  ShootingMisfit now = misfit(z);
  orbit.residuals.push_back(now.residual);
  ShootingPoint trial;
  while (!now.within(config.tolerance)) {
    if (orbit.iterations >= config.max_iterations)
      throw NumericalError("shooting: " + words.method + " did not converge in " + std::to_string(config.max_iterations) +
                           " iterations" + at() + " (relative residual " + format_number(now.residual) + ")");
    const ShootingPoint step = newton_step(z, now);
    bool accepted = false;
    double lambda = 1;
    for (int halving = 0; halving <= 10 && !accepted; ++halving, lambda /= 2) {
      trial.x.resize(z.x.size());
      for (std::size_t i = 0; i < z.x.size(); ++i) trial.x[i] = z.x[i] + lambda * step.x[i];
      trial.omega = z.omega + lambda * step.omega;
      ShootingMisfit tried = misfit(trial);
      if (tried.merit() < now.merit()) {
        accepted = true;
        now = std::move(tried);  // with the velocity it integrated
      }
    }
    if (!accepted)
      throw NumericalError("shooting: " + words.method + " stalled at relative residual " +
                           format_number(now.residual) + at());
    std::swap(z, trial);
    ++orbit.iterations;
    orbit.residuals.push_back(now.residual);
    if (euclidean_norm(z.x) < 1e-6 * guess_norm)
      throw NumericalError("shooting: " + words.method + " fell to the rest state (the trivial orbit)" + at());
  }
  orbit.x0 = std::move(z.x);
  orbit.omega = z.omega;
  orbit.period = 2 * std::numbers::pi / z.omega;
  orbit.time_step = orbit.period / static_cast<double>(steps_per_period);
  return orbit;
}

}  // namespace

PeriodicOrbit find_periodic_orbit(const ForceLaw& law, const Chain& chain, double omega,
                                  const std::vector<double>& guess, const ShootingConfig& config) {
  check_frequency(omega);
  const std::size_t n = chain.size();
  const bool krylov = uses_newton_krylov(n, config);
  if (config.max_krylov < 1) throw InvalidInput("max_krylov", ": must be >= 1");
  if (guess.size() != n) throw InvalidInput("guess", ": must have one displacement per bead");
  const std::size_t steps = config.steps_per_period > 0 ? config.steps_per_period : shooting_steps(chain, omega);
  if (krylov) {
    const detail::ShootingKrylov solver(law, chain, config.scheme, steps, omega, config.precondition);
    std::vector<int> iterations;
    std::vector<double> reached;
    // Inexact Newton: GMRES to a relative residual shrinking with the shooting residual r.
    const auto newton_step = [&](const ShootingPoint& z, const ShootingMisfit& at) {
      const double r = at.residual;
      const auto c = solver.solve(z.x, at.velocity, std::min(1e-3, std::max(1e-12, 0.1 * r)), config.max_krylov);
      iterations.push_back(c.iterations);
      reached.push_back(c.residual);
      if (!(c.residual <= 0.5))
        throw NumericalError("shooting: GMRES reached only relative residual " + format_number(c.residual) + " in " +
                             std::to_string(c.iterations) + " iterations at " + khz(omega) + " kHz");
      return ShootingPoint{c.step, 0};
    };
    const auto misfit = [&](const ShootingPoint& z) {
      auto velocity = half_period_map(law, chain, config.scheme, steps, omega, z.x, false).velocity;
      const double r = relative_residual(velocity, omega, z.x);
      return ShootingMisfit{r, 0, std::move(velocity)};
    };
    auto orbit = damped_newton({guess, omega}, {"Newton-Krylov", "at"}, config, steps, newton_step, misfit);
    orbit.newton = "krylov";
    orbit.krylov_iterations = std::move(iterations);
    orbit.krylov_residuals = std::move(reached);
    return orbit;
  }
  const auto map = [&](const std::vector<double>& x, bool jac) {
    return half_period_map(law, chain, config.scheme, steps, omega, x, jac);
  };
  const int nn = static_cast<int>(n);
  std::vector<int> pivots(n);
  // Newton on u̇(T/2; x) = 0 at fixed ω: J δx = −u̇.
  const auto newton_step = [&](const ShootingPoint& z, const ShootingMisfit&) {
    auto current = map(z.x, true);
    ShootingPoint step{std::move(current.velocity), 0};
    for (double& s : step.x) s = -s;
    int one = 1, info = 0;
    dgesv_(&nn, &one, current.jacobian.data(), &nn, pivots.data(), step.x.data(), &nn, &info);
    if (info != 0)
      throw NumericalError("shooting: the Jacobian is singular at " + khz(omega) +
                           " kHz (a linear mode at this frequency?)");
    return step;
  };
  const auto misfit = [&](const ShootingPoint& z) {
    return ShootingMisfit{relative_residual(map(z.x, false).velocity, omega, z.x), 0};
  };
  return damped_newton({guess, omega}, {"Newton", "at"}, config, steps, newton_step, misfit);
}

PeriodicOrbit find_periodic_orbit_on_arc(const ForceLaw& law, const Chain& chain, const ArcPrediction& p,
                                         const ShootingConfig& config) {
  check_frequency(p.omega);
  const std::size_t n = chain.size();
  const bool krylov = uses_newton_krylov(n, config);  // refuses dense beyond the dense limit
  if (config.max_krylov < 1) throw InvalidInput("max_krylov", ": must be >= 1");
  if (p.x.size() != n || p.tangent_x.size() != n)
    throw InvalidInput("guess", ": the prediction and its tangent must have one displacement per bead");
  if (config.steps_per_period == 0)
    throw InvalidInput("steps_per_period", ": must be set (fixed along the branch) for arclength continuation");
  if (!(p.x_scale > 0) || !(p.omega_scale > 0)) throw InvalidInput("guess", ": the scales must be > 0");
  const double xs = p.x_scale, ws = p.omega_scale;
  const auto map = [&](const std::vector<double>& x, double omega, bool jac) {
    return half_period_map(law, chain, config.scheme, config.steps_per_period, omega, x, jac);
  };
  // The arclength condition: the scaled correction from the prediction along the tangent.
  const auto along = [&](const ShootingPoint& z) {
    double s = p.tangent_omega * (z.omega - p.omega) / ws;
    for (std::size_t i = 0; i < n; ++i) s += p.tangent_x[i] * (z.x[i] - p.x[i]) / xs;
    return s;
  };
  const std::size_t m = n + 1;
  const int mm = static_cast<int>(m);
  std::vector<int> pivots(m);
  std::vector<double> a(krylov ? 0 : m * m), step(m);
  std::optional<detail::ShootingKrylov> solver;
  if (krylov) solver.emplace(law, chain, config.scheme, config.steps_per_period, p.omega, config.precondition);
  std::vector<int> gmres_iterations;
  std::vector<double> gmres_reached;
  // Matrix-free: GMRES on the same bordered system, the shooting rows' J v by tangent
  // integrations at the iterate's ω_b, to a relative residual shrinking with the misfit (inexact
  // Newton, as find_periodic_orbit's Krylov steps).
  const auto krylov_step = [&](const ShootingPoint& z, const ShootingMisfit& at) {
    solver->set_frequency(z.omega);
    const std::vector<double>& current = at.velocity;
    const double h = 1e-6 * z.omega;
    const auto up = map(z.x, z.omega + h, false), down = map(z.x, z.omega - h, false);
    const double row = 1 / (z.omega * xs);
    detail::BorderedSystem system{.jacobian_scale = xs * row,
                                  .column = std::vector<double>(n),
                                  .tangent_x = p.tangent_x,
                                  .tangent_omega = p.tangent_omega,
                                  .rhs = std::vector<double>(m)};
    for (std::size_t i = 0; i < n; ++i) {
      system.column[i] = (up.velocity[i] - down.velocity[i]) / (2 * h) * ws * row;
      system.rhs[i] = -current[i] * row;
    }
    system.rhs[n] = -at.arc;
    const double r = at.merit();
    const auto c = solver->solve_bordered(z.x, system, std::min(1e-3, std::max(1e-12, 0.1 * r)), config.max_krylov);
    gmres_iterations.push_back(c.iterations);
    gmres_reached.push_back(c.residual);
    if (!(c.residual <= 0.5))
      throw NumericalError("shooting: GMRES on the bordered arclength system reached only relative residual " +
                           format_number(c.residual) + " in " + std::to_string(c.iterations) + " iterations near " +
                           khz(z.omega) + " kHz");
    ShootingPoint out{std::vector<double>(n), c.step[n] * ws};
    for (std::size_t i = 0; i < n; ++i) out.x[i] = c.step[i] * xs;
    return out;
  };
  // Newton on the bordered system in scaled unknowns (δx/xs, δω/ωs), the shooting rows divided
  // by ω xs; ∂u̇/∂ω by central differences.
  const auto newton_step = [&](const ShootingPoint& z, const ShootingMisfit& at) {
    if (krylov) return krylov_step(z, at);
    const auto current = map(z.x, z.omega, true);
    const double h = 1e-6 * z.omega;
    const auto up = map(z.x, z.omega + h, false), down = map(z.x, z.omega - h, false);
    const double row = 1 / (z.omega * xs);
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t i = 0; i < n; ++i) a[j * m + i] = current.jacobian[j * n + i] * xs * row;
      a[j * m + n] = p.tangent_x[j];
    }
    for (std::size_t i = 0; i < n; ++i) a[n * m + i] = (up.velocity[i] - down.velocity[i]) / (2 * h) * ws * row;
    a[n * m + n] = p.tangent_omega;
    for (std::size_t i = 0; i < n; ++i) step[i] = -current.velocity[i] * row;
    step[n] = -along(z);
    int one = 1, info = 0;
    dgesv_(&mm, &one, a.data(), &mm, pivots.data(), step.data(), &mm, &info);
    if (info != 0)
      throw NumericalError("shooting: the bordered arclength system is singular near " + khz(z.omega) + " kHz");
    ShootingPoint out{std::vector<double>(n), step[n] * ws};
    for (std::size_t i = 0; i < n; ++i) out.x[i] = step[i] * xs;
    return out;
  };
  const auto misfit = [&](const ShootingPoint& z) {
    if (!(z.omega > 0)) return ShootingMisfit{inf, inf};
    auto velocity = map(z.x, z.omega, false).velocity;
    const double r = relative_residual(velocity, z.omega, z.x);
    return ShootingMisfit{r, along(z), std::move(velocity)};
  };
  auto orbit = damped_newton({p.x, p.omega}, {krylov ? "arclength Newton-Krylov" : "arclength Newton", "near"}, config,
                             config.steps_per_period, newton_step, misfit);
  if (krylov) {
    orbit.newton = "krylov";
    orbit.krylov_iterations = std::move(gmres_iterations);
    orbit.krylov_residuals = std::move(gmres_reached);
  }
  return orbit;
}

State turning_state(const PeriodicOrbit& orbit) {
  State s(orbit.x0.size());
  s.u = orbit.x0;
  return s;
}

}  // namespace granular
