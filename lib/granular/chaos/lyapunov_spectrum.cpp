#include "granular/chaos/lyapunov_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "granular/chaos/alignment_indices.hpp"
#include "granular/dynamics/detail/dense_lapack.hpp"
#include "granular/dynamics/detail/random_deviations.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

// The deviation vectors as the columns of a 2N × k matrix (column-major) in the norm's coordinates
// (δu, t_unit δv), and back (du, dv: scratch of N).
void as_matrix(const TangentPropagator& p, std::size_t n, std::size_t k, double t, std::vector<double>& a) {
  for (std::size_t j = 0; j < k; ++j) {
    const auto du = p.deviation_displacement(j), dv = p.deviation_velocity(j);
    for (std::size_t i = 0; i < n; ++i) {
      a[j * 2 * n + i] = du[i];
      a[j * 2 * n + n + i] = t * dv[i];
    }
  }
}

void from_matrix(TangentPropagator& p, const std::vector<double>& a, std::size_t n, std::size_t k, double t,
                 std::vector<double>& du, std::vector<double>& dv) {
  for (std::size_t j = 0; j < k; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      du[i] = a[j * 2 * n + i];
      dv[i] = a[j * 2 * n + n + i] / t;
    }
    p.set_deviation(j, du, dv);
  }
}

}  // namespace

std::vector<State> detail::random_deviation_vectors(std::size_t n, std::size_t k, std::uint64_t seed, double t) {
  std::uint64_t x = seed;
  const auto next = [&x] {
    std::uint64_t z = (x += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return 2 * (static_cast<double>(z >> 11) * 0x1.0p-53) - 1;
  };
  std::vector<State> w(k, State(n));
  for (State& s : w) {
    for (double& u : s.u) u = next();
    for (double& v : s.v) v = next() / t;
  }
  return w;
}

LyapunovSpectrum::LyapunovSpectrum(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                                   double time_step, const State& initial, const LyapunovSpectrumConfig& config)
    : config_(config), beads_(chain.size()), sums_(config.vectors, 0.0) {
  if (config.vectors < 1 || config.vectors > 2 * beads_)
    throw InvalidInput("vectors",
                       " " + std::to_string(config.vectors) + ": between 1 and 2N = " + std::to_string(2 * beads_));
  if (config.orthonormalize_every < 1) throw InvalidInput("orthonormalize_every", ": at least 1 step");
  tangent_ = make_tangent_propagator(
      law, chain, scheme, time_step, initial,
      detail::random_deviation_vectors(beads_, config.vectors, config.seed, config.time_unit),
      {.enabled = true, .renormalize_every = config.orthonormalize_every, .time_unit = config.time_unit},
      [this](TangentPropagator&) { orthonormalize(); });
  // The QR's buffers, and LAPACK's workspace asked for once (the larger of dgeqrf's and dorgqr's).
  matrix_.resize(2 * beads_ * config.vectors);
  tau_.resize(config.vectors);
  diagonal_.resize(config.vectors);
  du_.resize(beads_);
  dv_.resize(beads_);
  const int m = static_cast<int>(2 * beads_), k = static_cast<int>(config.vectors), query = -1;
  int info = 0;
  double qr = 0, q = 0;
  dgeqrf_(&m, &k, matrix_.data(), &m, tau_.data(), &qr, &query, &info);
  dorgqr_(&m, &k, &k, matrix_.data(), &m, tau_.data(), &q, &query, &info);
  work_.resize(static_cast<std::size_t>(std::max({qr, q, static_cast<double>(k)})));
  factorize();  // the random vectors made orthonormal; R not counted: t = 0
  from_matrix(*tangent_, matrix_, beads_, config.vectors, config.time_unit, du_, dv_);
}

void LyapunovSpectrum::advance(std::size_t steps) {
  tangent_->advance(steps);  // the map calls orthonormalize() every orthonormalize_every steps
  if (tangent_->steps_done() != orthonormalized_at_) orthonormalize();
}

void LyapunovSpectrum::factorize() {
  as_matrix(*tangent_, beads_, config_.vectors, config_.time_unit, matrix_);
  const int m = static_cast<int>(2 * beads_), k = static_cast<int>(config_.vectors),
            lwork = static_cast<int>(work_.size());
  int info = 0;
  dgeqrf_(&m, &k, matrix_.data(), &m, tau_.data(), work_.data(), &lwork, &info);
  if (info != 0) throw NumericalError("Lyapunov spectrum: dgeqrf failed (info " + std::to_string(info) + ")");
  for (std::size_t j = 0; j < config_.vectors; ++j) diagonal_[j] = matrix_[j * 2 * beads_ + j];
  if (record_) {
    const std::size_t k = config_.vectors;
    for (std::size_t j = 0; j < k; ++j)
      for (std::size_t i = 0; i < k; ++i) factor_[j * k + i] = i <= j ? matrix_[j * 2 * beads_ + i] : 0.0;
  }
  dorgqr_(&m, &k, &k, matrix_.data(), &m, tau_.data(), work_.data(), &lwork, &info);
  if (info != 0) throw NumericalError("Lyapunov spectrum: dorgqr failed (info " + std::to_string(info) + ")");
}

void LyapunovSpectrum::orthonormalize() {
  factorize();
  for (std::size_t j = 0; j < config_.vectors; ++j) {
    const double r = diagonal_[j];
    if (!(std::abs(r) > 0) || !std::isfinite(r))
      throw NumericalError("Lyapunov spectrum: deviation vector " + std::to_string(j + 1) + " became " +
                           (std::isfinite(r) ? "dependent on the others" : "non-finite"));
    sums_[j] += std::log(std::abs(r));
  }
  from_matrix(*tangent_, matrix_, beads_, config_.vectors, config_.time_unit, du_, dv_);
  orthonormalized_at_ = tangent_->steps_done();
  if (record_) record_(factor_);
}

void LyapunovSpectrum::record_factors(std::function<void(std::span<const double> r)> record) {
  record_ = std::move(record);
  factor_.assign(record_ ? config_.vectors * config_.vectors : 0, 0.0);
}

std::vector<double> LyapunovSpectrum::exponents() const {
  std::vector<double> out(sums_.size(), 0.0);
  const double t = time();
  if (t > 0)
    for (std::size_t j = 0; j < out.size(); ++j) out[j] = sums_[j] / t;
  return out;
}

std::vector<State> LyapunovSpectrum::vectors() const { return tangent_->deviations(); }

LyapunovSeries lyapunov_series(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme, double time_step,
                               const State& initial, const LyapunovSpectrumConfig& config,
                               const std::vector<std::uint64_t>& sample_steps) {
  if (!std::is_sorted(sample_steps.begin(), sample_steps.end())) throw InvalidInput("sample_steps", ": must be sorted");
  LyapunovSpectrum run(law, chain, scheme, time_step, initial, config);
  std::optional<FactorAlignment> alignment;
  if (config.vectors >= 2) {
    alignment.emplace(config.vectors);
    run.record_factors([&alignment](std::span<const double> r) { alignment->multiply(r); });
  }
  LyapunovSeries out;
  std::uint64_t done = 0;
  for (const std::uint64_t step : sample_steps) {
    run.advance(static_cast<std::size_t>(step - done));
    done = step;
    out.time.push_back(run.time());
    out.exponents.push_back(run.exponents());
    if (alignment) {
      out.gali.push_back(alignment->gali());
      out.sali.push_back(alignment->sali());
    }
  }
  return out;
}

}  // namespace granular
