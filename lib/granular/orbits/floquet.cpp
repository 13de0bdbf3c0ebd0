#include "granular/orbits/floquet.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "granular/detail/enum_names.hpp"
#include "granular/dynamics/detail/dense_lapack.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/error.hpp"
#include "granular/orbits/detail/floquet_verdict.hpp"

namespace granular {
namespace {

constexpr auto floquet_method_names =
    detail::enum_names<FloquetMethod>("floquet_method", {{FloquetMethod::automatic, "auto"},
                                                         {FloquetMethod::dense, "dense"},
                                                         {FloquetMethod::arpack, "arpack"}});

}  // namespace

std::vector<std::size_t> unit_pair(const std::vector<std::complex<double>>& multipliers, double window) {
  std::vector<std::size_t> near_one;
  for (std::size_t i = 0; i < multipliers.size(); ++i)
    if (std::abs(multipliers[i] - 1.0) <= window) near_one.push_back(i);
  std::stable_sort(near_one.begin(), near_one.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(multipliers[a] - 1.0) < std::abs(multipliers[b] - 1.0);
  });
  if (near_one.size() > 2) near_one.resize(2);
  return near_one;
}

void detail::decide_floquet_verdict(FloquetSpectrum& s, double tolerance, double unit_pair_window, double period) {
  const auto pair = unit_pair(s.multipliers, unit_pair_window);
  std::complex<double> worst = 0;
  for (std::size_t i = 0; i < s.multipliers.size(); ++i)
    if (std::find(pair.begin(), pair.end(), i) == pair.end() && std::abs(s.multipliers[i]) > std::abs(worst))
      worst = s.multipliers[i];
  s.tolerance = tolerance;
  s.max_modulus = std::abs(worst);
  const bool grows = s.max_modulus > 1 + tolerance;
  // A multiplier that converged and grows is an instability whatever else did not converge; no
  // growth among some of the largest says nothing about the others.
  s.stable = s.complete && !grows;
  s.growth_rate = std::log(s.max_modulus) / period;
  s.instability = grows        ? (std::abs(worst.imag()) <= tolerance * std::abs(worst) ? "real" : "oscillatory")
                  : s.complete ? "none"
                               : "unknown";
  s.unit_pair_distance =
      pair.size() == 2 ? std::abs(s.multipliers[pair[1]] - 1.0) : std::numeric_limits<double>::quiet_NaN();
}

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

FloquetSpectrum floquet_spectrum(std::vector<double> monodromy, std::size_t beads, double period, double tolerance,
                                 double unit_pair_window) {
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
  for (int i = 0; i < m; ++i) s.multipliers.emplace_back(wr[i], wi[i]);
  std::sort(s.multipliers.begin(), s.multipliers.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  detail::decide_floquet_verdict(s, tolerance, unit_pair_window, period);
  // dgeev returns conjugate pairs exactly (a real matrix): only the reciprocal pairs and the
  // product test the symplectic structure.
  std::complex<double> product = 1;
  for (const auto mu : s.multipliers) {
    double reciprocal = std::numeric_limits<double>::infinity();
    for (const auto nu : s.multipliers) reciprocal = std::min(reciprocal, std::abs(nu - 1.0 / mu));
    s.reciprocal_error = std::max(s.reciprocal_error, reciprocal / std::max(1.0, std::abs(mu)));
    product *= mu;
  }
  s.product_error = std::abs(product - 1.0);
  return s;
}

FloquetSpectrum floquet_stability(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit, double tolerance,
                                  double unit_pair_window) {
  auto s =
      floquet_spectrum(monodromy_matrix(law, chain, orbit), chain.size(), orbit.period, tolerance, unit_pair_window);
  s.operator_applications = static_cast<long>(2 * chain.size());
  return s;
}

FloquetSpectrum floquet_stability(const ForceLaw& law, const Chain& chain, const PeriodicOrbit& orbit,
                                  const FloquetConfig& config) {
  const bool automatic = config.method == FloquetMethod::automatic;
  if (config.method == FloquetMethod::dense || (automatic && chain.size() <= config.max_dense_beads))
    return floquet_stability(law, chain, orbit, config.tolerance, config.unit_pair_window);
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
  FloquetSpectrum s = floquet_stability(law, chain, orbit, config.tolerance, config.unit_pair_window);
  s.method = arnoldi.multipliers.empty() ? "dense (ARPACK converged none)"
                                         : "dense (ARPACK incomplete within the dense method's cost)";
  s.operator_applications += arnoldi.operator_applications;
  s.restarts = arnoldi.restarts;
  return s;
}

}  // namespace granular
