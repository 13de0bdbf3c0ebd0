#include "granular/case/time_step_rule.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"
#include "granular/linear/sym_tridiagonal.hpp"
#include "granular/model/disorder.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

using Matrix = std::array<double, 4>;  // row-major 2×2 on (x, v/ω)

Matrix times(const Matrix& a, const Matrix& b) {
  return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3]};
}

/// The radii whose arrangements bound a random chain of `c`: its two types (those the disorder
/// places), the k types of a bead distribution, or for polydisperse radii a geometric grid of 9
/// from the smallest to the largest (a truncated normal: mean + 8 sd, which no bead of any
/// realization passes with probability above ~1e-15).
}  // namespace

// One step on a harmonic mode, h = ωτ, in the order the stepper applies it: corrector, drift a_0,
// kick b_0, …, drift a_s, corrector. On a mode the corrector v += gτ³ M⁻¹K(−a) is v += g h³ ω x.
double step_trace(const SplittingScheme& s, double h) {
  const double g = s.corrector * h * h * h;
  Matrix m{1, 0, g, 1};
  for (std::size_t j = 0; j < s.drift.size(); ++j) {
    m = times(Matrix{1, s.drift[j] * h, 0, 1}, m);
    if (j < s.kick.size()) m = times(Matrix{1, 0, -s.kick[j] * h, 1}, m);
  }
  m = times(Matrix{1, 0, g, 1}, m);
  return m[0] + m[3];
}

namespace {

// The largest bond stiffness over the strains 0 … x where φ_k(x) reaches `energy` (compression;
// on the extension side every law here is softer than at rest).
template <class Law>
double stiffest(const Law& law, std::size_t k, double energy) {
  double hi = 1e-12;
  while (law.potential(k, hi) < energy && hi < 1) hi *= 2;
  double lo = 0;
  for (int i = 0; i < 100 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = (lo + hi) / 2;
    (law.potential(k, mid) < energy ? lo : hi) = mid;
  }
  double k_max = 0;
  for (int i = 0; i <= 64; ++i) k_max = std::max(k_max, law.stiffness(k, hi * i / 64));
  return k_max;
}

}  // namespace

namespace {

using Polynomial = std::vector<double>;  // coefficients of h^0, h^1, …

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  Polynomial c(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}

Polynomial operator+(Polynomial a, const Polynomial& b) {
  if (a.size() < b.size()) a.resize(b.size(), 0.0);
  for (std::size_t i = 0; i < b.size(); ++i) a[i] += b[i];
  return a;
}

// step_trace(s, h) as a polynomial in h: the same product with entries that are polynomials.
Polynomial trace_polynomial(const SplittingScheme& s) {
  using PolyMatrix = std::array<Polynomial, 4>;
  const auto times = [](const PolyMatrix& a, const PolyMatrix& b) {
    return PolyMatrix{a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2],
                      a[2] * b[1] + a[3] * b[3]};
  };
  const PolyMatrix corrector{Polynomial{1}, Polynomial{0}, Polynomial{0, 0, 0, s.corrector}, Polynomial{1}};
  PolyMatrix m = corrector;
  for (std::size_t j = 0; j < s.drift.size(); ++j) {
    m = times(PolyMatrix{Polynomial{1}, Polynomial{0, s.drift[j]}, Polynomial{0}, Polynomial{1}}, m);
    if (j < s.kick.size())
      m = times(PolyMatrix{Polynomial{1}, Polynomial{0}, Polynomial{0, -s.kick[j]}, Polynomial{1}}, m);
  }
  m = times(corrector, m);
  return m[0] + m[3];
}

// The real roots in (0, limit) of p, ascending, from the eigenvalues of its companion matrix
// (p's zero roots, those of trace − 2 at h = 0, removed first).
std::vector<double> positive_real_roots(Polynomial p, double limit) {
  double scale = 0;
  for (double c : p) scale = std::max(scale, std::fabs(c));
  for (double& c : p)
    if (std::fabs(c) <= 1e-15 * scale) c = 0;
  while (!p.empty() && p.back() == 0) p.pop_back();
  std::size_t zeros = 0;
  while (zeros < p.size() && p[zeros] == 0) ++zeros;
  p.erase(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(zeros));
  const auto degree = static_cast<Eigen::Index>(p.size()) - 1;
  if (degree < 1) return {};
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(degree, degree);
  for (Eigen::Index i = 1; i < degree; ++i) companion(i, i - 1) = 1;
  for (Eigen::Index i = 0; i < degree; ++i) companion(i, degree - 1) = -p[static_cast<std::size_t>(i)] / p.back();
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(companion, false);
  std::vector<double> roots;
  for (const auto& z : solver.eigenvalues())
    if (z.real() > 0 && z.real() < limit && std::fabs(z.imag()) <= 1e-6 * std::abs(z)) roots.push_back(z.real());
  std::sort(roots.begin(), roots.end());
  return roots;
}

}  // namespace

double stable_step_limit(const SplittingScheme& s) {
  // The first h where |trace| passes 2 is the smallest root of trace² − 4 at which the trace
  // crosses ±2 (a touch keeps the step stable). The roots come from the trace's polynomial, so no
  // unstable gap, however narrow, is stepped over; the bracket is then the one a scan in steps of
  // 1e-3 would give where that scan sees the gap (the same h* to the last bit), and bisection
  // takes it to full precision.
  const double step = 1e-3, limit = 20;
  const Polynomial trace = trace_polynomial(s);
  std::vector<double> roots = positive_real_roots(trace + Polynomial{-2}, limit);
  for (double r : positive_real_roots(trace + Polynomial{2}, limit)) roots.push_back(r);
  std::sort(roots.begin(), roots.end());
  const auto unstable = [&](double h) { return std::fabs(step_trace(s, h)) > 2; };
  double lo = 0, hi = 0;
  for (std::size_t i = 0; i < roots.size() && hi == 0; ++i) {
    // Is |trace| > 2 just past roots[i]: between it and the next root (or a little beyond it)?
    const double next = i + 1 < roots.size() ? roots[i + 1] : roots[i] * 1.01;
    const double inside = std::min(roots[i] + (next - roots[i]) / 2, roots[i] * (1 + 1e-3));
    if (!unstable(inside) && !unstable(next)) continue;
    double h = step;
    while (h < roots[i]) h += step;
    if (!unstable(h - step) && unstable(h)) {
      lo = h - step, hi = h;
    } else {  // a gap narrower than the scan's step
      lo = h - step;
      while (lo > 0 && unstable(lo)) lo -= step;
      hi = unstable(inside) ? inside : next;
    }
  }
  if (hi == 0) {  // no instability below the limit: what the scan ends with
    double h = step;
    while (h < limit && !unstable(h)) h += step;
    lo = h - step, hi = h;
  }
  for (int i = 0; i < 60; ++i) {
    const double mid = (lo + hi) / 2;
    (unstable(mid) ? hi : lo) = mid;
  }
  return lo;
}

double highest_frequency_bound(const ForceLaw& law, const Chain& chain, double energy) {
  return std::visit(
      [&](const auto& l) {
        std::vector<double> stiffness(chain.bonds());
        std::map<std::pair<double, double>, double> known;  // bonds of one kind: one search
        for (std::size_t k = 0; k < chain.bonds(); ++k) {
          const auto key = std::pair{chain.contact[k], chain.overlap[k]};
          auto it = known.find(key);
          if (it == known.end()) it = known.emplace(key, stiffest(l, k, energy)).first;
          stiffness[k] = it->second;
        }
        // Gershgorin on M^{-1/2} K M^{-1/2}: row i holds bonds i (left) and i+1 (right).
        const std::size_t n = chain.size();
        SymTridiagonal t;
        for (std::size_t i = 0; i < n; ++i)  // with the on-site spring, stiffest at this energy
          t.diagonal.push_back((stiffness[i] + stiffness[i + 1] + l.onsite_stiffness_bound(i, energy)) / chain.mass[i]);
        for (std::size_t i = 0; i + 1 < n; ++i)
          t.off_diagonal.push_back(stiffness[i + 1] / std::sqrt(chain.mass[i] * chain.mass[i + 1]));
        return std::sqrt(std::max(0.0, gershgorin_bounds(t, RowSum::left_to_right).second));
      },
      law);
}

std::vector<Chain> rule_chains(const TransportCase& c, const Chain* chain) {
  if (chain) return {*chain};
  if (!c.chain.drawn()) return {c.chain.chain(0)};
  if (const auto* q = c.chain.as<Quasiperiodic>())
    return quasiperiodic_local_chains(*q, c.chain.R1, c.chain.F0, c.chain.material);
  // Every local arrangement of the radii the chain can hold: three beads between walls hold
  // every neighbourhood of a bead (inside a chain, or next to a wall).
  std::vector<Chain> chains;
  const std::vector<double> radii = c.chain.possible_radii();
  for (double a : radii)
    for (double b : radii)
      for (double d : radii) chains.push_back(make_chain({a, b, d}, c.chain.F0, c.chain.material));
  return chains;
}

double kick_energy_bound(const TransportCase& c, const std::vector<Chain>& chains, bool whole_chain) {
  // The largest kick energy: at any bead of any arrangement. A mode of a chain not yet drawn has
  // its energy given, or bounded from α: the shape u = α w/max|w| moves every bond by at most 2α,
  // and each bond's excess energy at ±2α is at most that of a displacement kick ±2α of a bead
  // beside it (the other bond's share is ≥ 0), so H0 ≤ (N + 1) max φ(±2α) over every arrangement.
  // On the whole chain, the kick itself (the mode of that chain).
  const bool unknown_mode = c.kick == Kick::mode && !whole_chain;
  if (unknown_mode && c.mode.energy > 0) return c.mode.energy;
  TransportCase probe = c;
  double energy = 0, bond = 0;
  for (const Chain& ch : chains) {
    const ForceLaw law = make_force_law(c.dynamics.integration.force_law, ch);
    for (std::size_t site = 0; site < ch.size(); ++site) {
      if (whole_chain && site != kicked_bead(c)) continue;
      probe.site = site + 1;  // counting from 1
      if (!unknown_mode) energy = std::max(energy, total_energy(law, ch, kick(probe, ch).initial));
      else
        for (double sign : {1.0, -1.0})
          bond = std::max(bond, total_energy(law, ch, displacement_kick(ch, site, sign * 2 * c.alpha)));
    }
  }
  return unknown_mode ? static_cast<double>(c.chain.size() + 1) * bond : energy;
}

TimeStepLimit time_step_limit(const TransportCase& c, const Chain* chain) {
  TimeStepLimit limit;
  const std::vector<Chain> chains = rule_chains(c, chain);
  const double energy = kick_energy_bound(c, chains, chain || !c.chain.drawn());
  for (const Chain& ch : chains)
    limit.omega_max =
        std::max(limit.omega_max,
                 highest_frequency_bound(make_force_law(c.dynamics.integration.force_law, ch), ch, energy));
  if (c.dynamics.integration.integrator.reference)
    return limit;  // adaptive: no step to bound (ω_max still bounds the waves)
  limit.scheme_limit = stable_step_limit(c.dynamics.integration.integrator.scheme);
  limit.max_time_step = limit.scheme_limit / limit.omega_max;
  return limit;
}

double default_time_step(const TimeStepLimit& limit, double preferred) {
  const double bound = limit.max_time_step / default_step_margin;
  if (!(preferred > bound)) return preferred;
  return preferred / std::ceil(preferred / bound);
}

void check_time_step(const TransportCase& c, const TimeStepLimit& limit) {
  if (c.dynamics.integration.time_step > limit.max_time_step)
    throw InvalidInput("time_step", " " + format_number(c.dynamics.integration.time_step) +
                                        " s: past the stability limit of " + c.dynamics.integration.integrator.name() +
                                        " on this chain; the largest stable time step is " +
                                        format_number(limit.max_time_step) +
                                        " s (h* = " + format_number(limit.scheme_limit) +
                                        ", omega_max = " + format_number(limit.omega_max) + " rad/s)");
}

nlohmann::json to_json(const TimeStepLimit& limit) {
  const bool bounded = std::isfinite(limit.max_time_step);
  return {{"rule",
           "tau <= h*/omega_max (h*: the scheme's largest stable omega*tau; omega_max: Gershgorin bound with every "
           "bond at the stiffest strain the kick energy reaches); default tau = 1e-6 s, or 1e-6/k s with the "
           "smallest integer k giving tau <= max_time_step/6"},
          {"scheme_limit", bounded ? nlohmann::json(limit.scheme_limit) : nlohmann::json(nullptr)},
          {"omega_max_rad_s", limit.omega_max},
          {"max_time_step_s", bounded ? nlohmann::json(limit.max_time_step) : nlohmann::json(nullptr)}};
}

nlohmann::json settle_time_step(std::vector<TransportCase>& cases, const Chain* chain) {
  TimeStepLimit tightest;
  for (TransportCase& c : cases) {
    const TimeStepLimit limit = time_step_limit(c, chain);
    if (limit.max_time_step < tightest.max_time_step) tightest = limit;
    tightest.omega_max = std::max(tightest.omega_max, limit.omega_max);  // the same scheme: the tightest has it
    if (c.time_step) {
      c.dynamics.integration.time_step = *c.time_step;
      check_time_step(c, limit);
    }
  }
  const bool given = !cases.empty() && cases.front().time_step.has_value();
  const double tau = cases.empty() ? 0 : default_time_step(tightest, cases.front().dynamics.integration.time_step);
  for (TransportCase& c : cases) {
    if (!c.time_step) c.dynamics.integration.time_step = tau;
    c.time_step = c.dynamics.integration.time_step;  // settled
  }
  nlohmann::json rule = to_json(tightest);
  if (!cases.empty()) rule["time_step_s"] = cases.front().dynamics.integration.time_step;
  rule["time_step_given"] = given;
  return rule;
}

nlohmann::json settle_time_step(TransportCase& c, const Chain* chain) {
  std::vector<TransportCase> one{c};
  const nlohmann::json rule = settle_time_step(one, chain);
  c = one.front();
  return rule;
}

}  // namespace granular
