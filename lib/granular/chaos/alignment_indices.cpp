#include "granular/chaos/alignment_indices.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "granular/dynamics/detail/dense_lapack.hpp"
#include "granular/dynamics/detail/random_deviations.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

// ‖w‖ in the norm's coordinates (δu, t_unit δv).
double alignment_norm(std::span<const double> du, std::span<const double> dv, double t) {
  double s = 0;
  for (std::size_t i = 0; i < du.size(); ++i) s += du[i] * du[i] + t * t * dv[i] * dv[i];
  return std::sqrt(s);
}

// Column j of the 2N × k column-major matrix `a`: the unit vector of (δu, t_unit δv).
void alignment_unit_column(std::span<const double> du, std::span<const double> dv, double t, std::size_t j,
                           std::vector<double>& a) {
  const std::size_t n = du.size();
  const double norm = alignment_norm(du, dv, t);
  if (!(norm > 0) || !std::isfinite(norm))
    throw InvalidInput("vectors", " " + std::to_string(j + 1) + ": must be finite and non-zero");
  for (std::size_t i = 0; i < n; ++i) {
    a[j * 2 * n + i] = du[i] / norm;
    a[j * 2 * n + n + i] = t * dv[i] / norm;
  }
}

// GALI_2 … GALI_k of the unit columns of `a` (destroyed: it becomes the QR), as |Π_{i≤j} R_ii|
// (Householder QR, LAPACK dgeqrf; `work` of at least k, more for speed).
void alignment_gali(std::vector<double>& a, std::size_t rows, std::size_t k, std::vector<double>& tau,
                    std::vector<double>& work, std::vector<double>& out) {
  const int m = static_cast<int>(rows), n = static_cast<int>(k), lwork = static_cast<int>(work.size());
  int info = 0;
  dgeqrf_(&m, &n, a.data(), &m, tau.data(), work.data(), &lwork, &info);
  if (info != 0) throw NumericalError("alignment indices: dgeqrf failed (info " + std::to_string(info) + ")");
  out.resize(k - 1);
  double product = std::abs(a[0]);
  for (std::size_t j = 1; j < k; ++j) {
    product *= std::abs(a[j * rows + j]);
    out[j - 1] = product;
  }
}

// SALI of the first two unit columns of `a`.
double alignment_sali(const std::vector<double>& a, std::size_t rows) {
  double plus = 0, minus = 0;
  for (std::size_t i = 0; i < rows; ++i) {
    const double x = a[i], y = a[rows + i];
    plus += (x + y) * (x + y);
    minus += (x - y) * (x - y);
  }
  return std::sqrt(std::min(plus, minus));
}

std::vector<double> alignment_workspace(std::size_t rows, std::size_t k) {
  const int m = static_cast<int>(rows), n = static_cast<int>(k), query = -1;
  int info = 0;
  double size = 0, a = 0, tau = 0;
  dgeqrf_(&m, &n, &a, &m, &tau, &size, &query, &info);
  return std::vector<double>(static_cast<std::size_t>(std::max(size, static_cast<double>(k))));
}

void check_alignment_vectors(const std::vector<State>& vectors) {
  if (vectors.size() < 2) throw InvalidInput("vectors", " " + std::to_string(vectors.size()) + ": at least 2 vectors");
  const std::size_t n = vectors.front().u.size();
  if (vectors.size() > 2 * n)
    throw InvalidInput("vectors", " " + std::to_string(vectors.size()) + ": at most 2N = " + std::to_string(2 * n));
  for (const State& w : vectors)
    if (w.u.size() != n || w.v.size() != n) throw InvalidInput("vectors", ": must all have N entries in u and v");
}

}  // namespace

std::vector<double> generalized_alignment_indices(const std::vector<State>& vectors, double time_unit) {
  check_alignment_vectors(vectors);
  const std::size_t n = vectors.front().u.size(), k = vectors.size();
  std::vector<double> a(2 * n * k), tau(k), out;
  for (std::size_t j = 0; j < k; ++j) alignment_unit_column(vectors[j].u, vectors[j].v, time_unit, j, a);
  std::vector<double> work = alignment_workspace(2 * n, k);
  alignment_gali(a, 2 * n, k, tau, work, out);
  return out;
}

double generalized_alignment_index(const std::vector<State>& vectors, double time_unit) {
  return generalized_alignment_indices(vectors, time_unit).back();
}

double smaller_alignment_index(const State& a, const State& b, double time_unit) {
  check_alignment_vectors({a, b});
  const std::size_t n = a.u.size();
  std::vector<double> m(4 * n);
  alignment_unit_column(a.u, a.v, time_unit, 0, m);
  alignment_unit_column(b.u, b.v, time_unit, 1, m);
  return alignment_sali(m, 2 * n);
}

AlignmentIndices::AlignmentIndices(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                                   double time_step, const State& initial, const AlignmentConfig& config)
    : config_(config), beads_(chain.size()) {
  if (config.vectors < 2 || config.vectors > 2 * beads_)
    throw InvalidInput("vectors",
                       " " + std::to_string(config.vectors) + ": between 2 and 2N = " + std::to_string(2 * beads_));
  if (!(config.time_unit > 0) || !std::isfinite(config.time_unit))
    throw InvalidInput("time_unit", ": must be finite and > 0");
  // LyapunovSpectrum's starting vectors: its random vectors through the same dgeqrf/dorgqr calls.
  const std::size_t m = 2 * beads_, k = config.vectors;
  const std::vector<State> raw = detail::random_deviation_vectors(beads_, k, config.seed, config.time_unit);
  std::vector<double> a(m * k), tau(k);
  for (std::size_t j = 0; j < k; ++j)
    for (std::size_t i = 0; i < beads_; ++i) {
      a[j * m + i] = raw[j].u[i];
      a[j * m + beads_ + i] = config.time_unit * raw[j].v[i];
    }
  const int rows = static_cast<int>(m), cols = static_cast<int>(k), query = -1;
  int info = 0;
  double qr = 0, q = 0;
  dgeqrf_(&rows, &cols, a.data(), &rows, tau.data(), &qr, &query, &info);
  dorgqr_(&rows, &cols, &cols, a.data(), &rows, tau.data(), &q, &query, &info);
  std::vector<double> work(static_cast<std::size_t>(std::max({qr, q, static_cast<double>(k)})));
  const int lwork = static_cast<int>(work.size());
  dgeqrf_(&rows, &cols, a.data(), &rows, tau.data(), work.data(), &lwork, &info);
  if (info == 0) dorgqr_(&rows, &cols, &cols, a.data(), &rows, tau.data(), work.data(), &lwork, &info);
  if (info != 0) throw NumericalError("alignment indices: the starting QR failed (info " + std::to_string(info) + ")");
  std::vector<State> vectors(k, State(beads_));
  for (std::size_t j = 0; j < k; ++j)
    for (std::size_t i = 0; i < beads_; ++i) {
      vectors[j].u[i] = a[j * m + i];
      vectors[j].v[i] = a[j * m + beads_ + i] / config.time_unit;
    }
  start(law, chain, scheme, time_step, initial, vectors);
}

AlignmentIndices::AlignmentIndices(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                                   double time_step, const State& initial, const std::vector<State>& start_vectors,
                                   const AlignmentConfig& config)
    : config_(config), beads_(chain.size()) {
  if (!(config.time_unit > 0) || !std::isfinite(config.time_unit))
    throw InvalidInput("time_unit", ": must be finite and > 0");
  config_.vectors = start_vectors.size();
  check_alignment_vectors(start_vectors);
  if (start_vectors.front().u.size() != beads_) throw InvalidInput("vectors", ": must have one entry per bead");
  for (std::size_t j = 0; j < start_vectors.size(); ++j) {
    const double norm = alignment_norm(start_vectors[j].u, start_vectors[j].v, config.time_unit);
    if (!(norm > 0) || !std::isfinite(norm))
      throw InvalidInput("vectors", " " + std::to_string(j + 1) + ": must be finite and non-zero");
  }
  start(law, chain, scheme, time_step, initial, start_vectors);
}

void AlignmentIndices::start(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme, double time_step,
                             const State& initial, const std::vector<State>& vectors) {
  if (config_.renormalize_every < 1) throw InvalidInput("renormalize_every", ": at least 1 step");
  if (!(config_.threshold > 0) || !std::isfinite(config_.threshold))
    throw InvalidInput("threshold", ": must be finite and > 0");
  const std::size_t k = config_.vectors;
  matrix_.resize(2 * beads_ * k);
  tau_.resize(k);
  du_.resize(beads_);
  dv_.resize(beads_);
  work_ = alignment_workspace(2 * beads_, k);
  gali_below_.assign(k - 1, std::nullopt);
  tangent_ = make_tangent_propagator(law, chain, scheme, time_step, initial, vectors,
                                     {.enabled = true,
                                      .renormalize_every = config_.renormalize_every,
                                      .time_unit = config_.time_unit},
                                     [this](TangentPropagator&) { renormalize(); });
  renormalize();  // unit lengths; the starting indices (t = 0 may already be below the threshold)
}

void AlignmentIndices::advance(std::size_t steps) {
  tangent_->advance(steps);  // the map calls renormalize() every renormalize_every steps
  if (tangent_->steps_done() != renormalized_at_) renormalize();
}

void AlignmentIndices::renormalize() {
  const double t = config_.time_unit;
  const std::size_t k = config_.vectors, m = 2 * beads_;
  for (std::size_t j = 0; j < k; ++j) {
    const auto du = tangent_->deviation_displacement(j), dv = tangent_->deviation_velocity(j);
    const double norm = alignment_norm(du, dv, t);
    if (!(norm > 0) || !std::isfinite(norm))
      throw NumericalError("alignment indices: deviation vector " + std::to_string(j + 1) + " became " +
                           (std::isfinite(norm) ? "zero" : "non-finite"));
    for (std::size_t i = 0; i < beads_; ++i) {
      du_[i] = du[i] / norm;
      dv_[i] = dv[i] / norm;
      matrix_[j * m + i] = du_[i];
      matrix_[j * m + beads_ + i] = t * dv_[i];
    }
    tangent_->set_deviation(j, du_, dv_);
  }
  sali_ = alignment_sali(matrix_, m);
  alignment_gali(matrix_, m, k, tau_, work_, gali_);
  const double now = tangent_->time();
  for (std::size_t j = 0; j + 1 < k; ++j)
    if (!gali_below_[j] && gali_[j] < config_.threshold) gali_below_[j] = now;
  if (!sali_below_ && sali_ < config_.threshold) sali_below_ = now;
  renormalized_at_ = tangent_->steps_done();
}

std::vector<State> AlignmentIndices::vectors() const { return tangent_->deviations(); }

FactorAlignment::FactorAlignment(std::size_t vectors) : k_(vectors), p_(vectors * vectors, 0.0), next_(p_) {
  if (vectors < 2) throw InvalidInput("vectors", " " + std::to_string(vectors) + ": at least 2 vectors");
  for (std::size_t j = 0; j < k_; ++j) p_[j * k_ + j] = 1;
}

void FactorAlignment::multiply(std::span<const double> r) {
  if (r.size() != k_ * k_) throw InvalidInput("r", ": must be k x k");
  for (std::size_t j = 0; j < k_; ++j) {  // both upper triangular: (R P)_ij = Σ_{i≤l≤j} R_il P_lj
    double norm = 0;
    for (std::size_t i = 0; i < k_; ++i) {
      double s = 0;
      for (std::size_t l = i; l <= j; ++l) s += r[l * k_ + i] * p_[j * k_ + l];
      next_[j * k_ + i] = s;
      norm += s * s;
    }
    norm = std::sqrt(norm);
    if (!(norm > 0) || !std::isfinite(norm))
      throw NumericalError("alignment indices: deviation vector " + std::to_string(j + 1) + " became " +
                           (std::isfinite(norm) ? "zero" : "non-finite"));
    for (std::size_t i = 0; i < k_; ++i) next_[j * k_ + i] /= norm;
  }
  p_.swap(next_);
}

std::vector<double> FactorAlignment::gali() const {
  std::vector<double> out(k_ - 1);
  double product = std::abs(p_[0]);
  for (std::size_t j = 1; j < k_; ++j) out[j - 1] = product *= std::abs(p_[j * k_ + j]);
  return out;
}

double FactorAlignment::sali() const {
  // p̂_1 = (±1, 0, …), p̂_2 = (a, b, 0, …): the angle from its sine |b|, so that small ones keep their digits.
  const double theta = std::atan2(std::abs(p_[k_ + 1]), std::copysign(1.0, p_[0]) * p_[k_]);
  return 2 * std::min(std::sin(theta / 2), std::cos(theta / 2));
}

AlignmentSeries alignment_series(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                                 double time_step, const State& initial, const AlignmentConfig& config,
                                 const std::vector<std::uint64_t>& sample_steps) {
  if (!std::is_sorted(sample_steps.begin(), sample_steps.end())) throw InvalidInput("sample_steps", ": must be sorted");
  AlignmentIndices run(law, chain, scheme, time_step, initial, config);
  AlignmentSeries out;
  std::uint64_t done = 0;
  for (const std::uint64_t step : sample_steps) {
    run.advance(static_cast<std::size_t>(step - done));
    done = step;
    out.time.push_back(run.time());
    out.gali.push_back(run.gali());
    out.sali.push_back(run.sali());
  }
  out.gali_below = run.gali_below();
  out.sali_below = run.sali_below();
  return out;
}

}  // namespace granular
