#include "granular/dynamics/floquet.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "granular/detail/enum_names.hpp"
#include "granular/dynamics/detail/dense_lapack.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

constexpr auto floquet_method_names =
    detail::enum_names<FloquetMethod>("floquet_method", {{FloquetMethod::automatic, "auto"},
                                                         {FloquetMethod::dense, "dense"},
                                                         {FloquetMethod::arpack, "arpack"}});

}  // namespace

FloquetMethod parse_floquet_method(const std::string& name) { return floquet_method_names.parse(name); }
std::string to_string(FloquetMethod method) { return std::string(floquet_method_names.name_of(method)); }

std::vector<double> apply_monodromy(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                                    const std::vector<double>& w) {
  const std::size_t n = chain.size();
  if (w.size() != 2 * n) throw InvalidInput("deviation", ": must have 2N entries (du, dv/omega_b)");
  const double omega = orbit.omega;
  std::vector<State> column(1, State(n));
  for (std::size_t i = 0; i < n; ++i) {
    column[0].u[i] = w[i];
    column[0].v[i] = omega * w[n + i];
  }
  const auto images = propagate_deviations(law, chain, orbit.scheme, orbit.time_step, orbit.steps_per_period,
                                           turning_state(orbit), column);
  std::vector<double> out(2 * n);
  const State& d = images.deviations[0];
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = d.u[i];
    out[n + i] = d.v[i] / omega;
  }
  return out;
}

std::vector<double> monodromy_matrix(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit) {
  const std::size_t n = chain.size(), m = 2 * n;
  const double w = orbit.omega;
  std::vector<State> columns(m, State(n));
  for (std::size_t j = 0; j < n; ++j) {
    columns[j].u[j] = 1;
    columns[n + j].v[j] = w;  // δv/ω_b = 1
  }
  const auto images = propagate_deviations(law, chain, orbit.scheme, orbit.time_step, orbit.steps_per_period,
                                           turning_state(orbit), columns);
  std::vector<double> out(m * m);
  for (std::size_t j = 0; j < m; ++j) {
    const State& d = images.deviations[j];
    for (std::size_t i = 0; i < n; ++i) {
      out[j * m + i] = d.u[i];
      out[j * m + n + i] = d.v[i] / w;
    }
  }
  return out;
}

FloquetSpectrum floquet_spectrum(std::vector<double> monodromy, std::size_t beads, double period, double tolerance) {
  const int m = static_cast<int>(2 * beads);
  if (monodromy.size() != 4 * beads * beads) throw InvalidInput("monodromy", ": must be 2N x 2N");
  std::vector<double> wr(m), wi(m);
  int lwork = -1, info = 0, one = 1;
  double query = 0, dummy = 0;
  dgeev_("N", "N", &m, monodromy.data(), &m, wr.data(), wi.data(), &dummy, &one, &dummy, &one, &query, &lwork, &info, 1,
         1);
  lwork = static_cast<int>(query);
  std::vector<double> work(static_cast<std::size_t>(std::max(lwork, 4 * m)));
  lwork = static_cast<int>(work.size());
  dgeev_("N", "N", &m, monodromy.data(), &m, wr.data(), wi.data(), &dummy, &one, &dummy, &one, work.data(), &lwork,
         &info, 1, 1);
  if (info != 0) throw NumericalError("floquet: dgeev failed (info " + std::to_string(info) + ")");

  FloquetSpectrum s;
  s.tolerance = tolerance;
  for (int i = 0; i < m; ++i) s.multipliers.emplace_back(wr[i], wi[i]);
  std::sort(s.multipliers.begin(), s.multipliers.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  // The two multipliers nearest +1 are the symmetry pair (phase, family): a Jordan block that
  // an orbit periodic to a residual r splits by ~√r, either onto the circle or off it along the
  // real axis. They say nothing about stability and are left out of its verdict.
  std::vector<std::size_t> order(s.multipliers.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(s.multipliers[a] - 1.0) < std::abs(s.multipliers[b] - 1.0);
  });
  std::complex<double> worst = 1;
  for (std::size_t k = std::min<std::size_t>(2, order.size()); k < order.size(); ++k)
    if (std::abs(s.multipliers[order[k]]) > std::abs(worst)) worst = s.multipliers[order[k]];
  s.max_modulus = std::abs(worst);
  s.stable = s.max_modulus <= 1 + tolerance;
  s.growth_rate = std::log(s.max_modulus) / period;
  if (!s.stable) s.instability = std::abs(worst.imag()) <= tolerance * std::abs(worst) ? "real" : "oscillatory";
  std::complex<double> product = 1;
  std::vector<double> to_one;
  for (const auto mu : s.multipliers) {
    double reciprocal = std::numeric_limits<double>::infinity(), conjugate = reciprocal;
    for (const auto nu : s.multipliers) {
      reciprocal = std::min(reciprocal, std::abs(nu - 1.0 / mu));
      conjugate = std::min(conjugate, std::abs(nu - std::conj(mu)));
    }
    const double scale = std::max(1.0, std::abs(mu));
    s.reciprocal_error = std::max(s.reciprocal_error, reciprocal / scale);
    s.conjugate_error = std::max(s.conjugate_error, conjugate / scale);
    product *= mu;
    to_one.push_back(std::abs(mu - 1.0));
  }
  s.product_error = std::abs(product - 1.0);
  std::sort(to_one.begin(), to_one.end());
  s.unit_pair_distance = to_one.size() >= 2 ? to_one[1] : 0;
  return s;
}

FloquetSpectrum floquet_stability(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit, double tolerance) {
  auto s = floquet_spectrum(monodromy_matrix(law, chain, orbit), chain.size(), orbit.period, tolerance);
  s.operator_applications = static_cast<long>(2 * chain.size());
  return s;
}

FloquetSpectrum floquet_stability(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                                  const FloquetConfig& config) {
  const bool automatic = config.method == FloquetMethod::automatic;
  if (config.method == FloquetMethod::dense || (automatic && chain.size() <= config.max_dense_beads))
    return floquet_stability(law, chain, orbit, config.tolerance);
  if (!automatic || chain.size() > config.max_fallback_beads)
    return largest_floquet_multipliers(law, chain, orbit, config);
  // Where the dense method is affordable, ARPACK gets its cost: about 2N applications of M, the
  // tangent integrations of the dense matrix. On a stable orbit every |μ| = 1: no modulus gap, and
  // Arnoldi seldom converges within it (N = 101: 172 restarts, 3409 applications), while past it the
  // dense method is the cheaper. So the whole costs at most about twice the dense method, and says
  // what ran.
  const long dense_cost = 2 * static_cast<long>(chain.size());
  const int ncv = floquet_subspace(config, chain.size()), shifts = std::max(1, ncv - config.multipliers);
  FloquetConfig budget = config;
  budget.max_restarts = static_cast<int>(std::clamp<long>((dense_cost - ncv) / shifts, 1, config.max_restarts));
  const FloquetSpectrum arnoldi = try_largest_floquet_multipliers(law, chain, orbit, budget);
  if (arnoldi.complete) return arnoldi;
  FloquetSpectrum s = floquet_stability(law, chain, orbit, config.tolerance);
  s.method = arnoldi.multipliers.empty() ? "dense (ARPACK converged none)"
                                         : "dense (ARPACK incomplete within the dense method's cost)";
  s.operator_applications += arnoldi.operator_applications;
  s.restarts = arnoldi.restarts;
  return s;
}

}  // namespace granular
