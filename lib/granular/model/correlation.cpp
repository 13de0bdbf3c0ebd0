#include "granular/model/correlation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granular {

std::vector<double> cyclic_correlation(const Configuration& types, std::size_t max_distance) {
  const std::size_t n = types.size();
  std::vector<double> rho(max_distance + 1, std::numeric_limits<double>::quiet_NaN());
  if (n == 0) return rho;
  double ones = 0;
  for (auto t : types) ones += t == 2;
  const double mean = ones / static_cast<double>(n);
  const double variance = mean - mean * mean;  // v ∈ {0,1}: mean(v²) = mean(v)
  if (!(variance > 0)) return rho;
  for (std::size_t d = 0; d <= max_distance; ++d) {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += (types[i] == 2) && (types[(i + d) % n] == 2);
    rho[d] = (sum / static_cast<double>(n) - mean * mean) / variance;
  }
  return rho;
}

std::vector<double> cyclic_value_correlation(const std::vector<double>& x, std::size_t max_distance) {
  const std::size_t n = x.size();
  std::vector<double> rho(max_distance + 1, std::numeric_limits<double>::quiet_NaN());
  if (n == 0 || std::all_of(x.begin(), x.end(), [&](double v) { return v == x[0]; })) return rho;
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(n);
  std::vector<double> c(n);  // centred first: no cancellation between mean(x x_d) and mean²
  for (std::size_t i = 0; i < n; ++i) c[i] = x[i] - mean;
  double variance = 0;
  for (double v : c) variance += v * v;
  for (std::size_t d = 0; d <= max_distance; ++d) {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += c[i] * c[(i + d) % n];
    rho[d] = sum / variance;
  }
  return rho;
}

double correlation_theory(const BeadDistribution& b, std::size_t d) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (b.kind == BeadDistribution::Kind::uniform) return b.high > b.low ? (d == 0 ? 1.0 : 0.0) : nan;
  if (b.kind == BeadDistribution::Kind::normal) return d == 0 ? 1.0 : 0.0;
  // Types: only those drawn (p > 0; RDM2 always places both) and of distinct radii vary the mass.
  std::vector<double> drawn;
  for (std::size_t t = 0; t < b.radii.size(); ++t)
    if (b.probabilities[t] > 0 || b.rule == Disorder::rdm2) drawn.push_back(b.radii[t]);  // 12/21: both
  if (std::all_of(drawn.begin(), drawn.end(), [&](double r) { return r == drawn[0]; })) return nan;
  if (b.rule == Disorder::rdm2) return correlation_theory(Disorder::rdm2, b.probabilities[0], d);
  return correlation_theory(b.rule, 0.5, d);  // A or RDM1 with both kinds of bead: q-independent
}

double correlation_theory(Disorder disorder, double q, std::size_t d) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  switch (disorder) {
    case Disorder::homogeneous: return nan;
    case Disorder::anderson: return (q == 0 || q == 1) ? nan : (d == 0 ? 1.0 : 0.0);
    case Disorder::rdm1: return (q == 0 || q == 1) ? nan : d == 0 ? 1.0 : d == 1 ? 0.5 : 0.0;
    case Disorder::rdm2: {
      const double s = (2 * q - 1) * (2 * q - 1);
      if (d == 0) return 1.0;
      if (d == 1) return -0.5 * (s + 1);
      return (d % 2 == 0 ? 1.0 : -1.0) * s;
    }
  }
  return nan;
}

}  // namespace granular
