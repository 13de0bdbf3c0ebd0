#include "granular/chaos/covariant_vectors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "granular/chaos/lyapunov_spectrum.hpp"
#include "granular/detail/memory_limit.hpp"
#include "granular/dynamics/detail/dense_lapack.hpp"
#include "granular/dynamics/detail/random_deviations.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

// The columns of a rows × cols column-major matrix made orthonormal in place (Householder QR,
// LAPACK dgeqrf/dorgqr); false if they are dependent (an |R_jj| at rounding level) or not finite.
bool clv_orthonormalize(std::vector<double>& a, std::size_t rows, std::size_t cols) {
  const int m = static_cast<int>(rows), n = static_cast<int>(cols), query = -1;
  int info = 0;
  std::vector<double> tau(cols);
  double qr = 0, q = 0;
  dgeqrf_(&m, &n, a.data(), &m, tau.data(), &qr, &query, &info);
  dorgqr_(&m, &n, &n, a.data(), &m, tau.data(), &q, &query, &info);
  std::vector<double> work(static_cast<std::size_t>(std::max({qr, q, static_cast<double>(cols)})));
  const int lwork = static_cast<int>(work.size());
  double largest = 0;
  for (double x : a) largest = std::max(largest, std::abs(x));
  dgeqrf_(&m, &n, a.data(), &m, tau.data(), work.data(), &lwork, &info);
  if (info != 0) return false;
  for (std::size_t j = 0; j < cols; ++j) {
    const double r = std::abs(a[j * rows + j]);
    if (!std::isfinite(r) || !(r > 1e-13 * largest)) return false;
  }
  dorgqr_(&m, &n, &n, a.data(), &m, tau.data(), work.data(), &lwork, &info);
  return info == 0;
}

// The singular values of a rows × cols matrix (destroyed), largest first (LAPACK dgesvd).
std::vector<double> clv_singular_values(std::vector<double>& a, std::size_t rows, std::size_t cols) {
  const int m = static_cast<int>(rows), n = static_cast<int>(cols), one = 1, query = -1;
  int info = 0;
  std::vector<double> s(std::min(rows, cols));
  double size = 0, dummy = 0;
  dgesvd_("N", "N", &m, &n, a.data(), &m, s.data(), &dummy, &one, &dummy, &one, &size, &query, &info, 1, 1);
  std::vector<double> work(static_cast<std::size_t>(std::max(size, 1.0)));
  const int lwork = static_cast<int>(work.size());
  dgesvd_("N", "N", &m, &n, a.data(), &m, s.data(), &dummy, &one, &dummy, &one, work.data(), &lwork, &info, 1, 1);
  if (info != 0) throw NumericalError("covariant vectors: dgesvd failed (info " + std::to_string(info) + ")");
  return s;
}

// The smallest principal angle between span(A) (rows × p, orthonormal columns) and span(B)
// (rows × q, independent columns; destroyed). The sine is the smallest singular value of
// Q_B − A Aᵀ Q_B (exact for small angles, where 1 − cos² would lose them), the cosine the largest of
// Aᵀ Q_B; false if B's columns are dependent.
bool clv_smallest_angle(const std::vector<double>& a, std::size_t rows, std::size_t p, std::vector<double>& b,
                        std::size_t q, double& angle) {
  if (!clv_orthonormalize(b, rows, q)) return false;
  std::vector<double> projection(p * q, 0.0), rest(b);
  for (std::size_t c = 0; c < q; ++c)
    for (std::size_t l = 0; l < p; ++l) {
      double dot = 0;
      for (std::size_t r = 0; r < rows; ++r) dot += a[l * rows + r] * b[c * rows + r];
      projection[c * p + l] = dot;
      for (std::size_t r = 0; r < rows; ++r) rest[c * rows + r] -= dot * a[l * rows + r];
    }
  const double cosine = clv_singular_values(projection, p, q).front();
  const double sine = clv_singular_values(rest, rows, q).back();
  angle = std::atan2(sine, cosine);
  return true;
}

// A set of States as the columns of a 2N × k matrix in the norm's coordinates (δu, t_unit δv).
std::vector<double> clv_columns(const std::vector<State>& w, double t) {
  if (w.empty()) throw InvalidInput("vectors", ": at least one vector in each set");
  const std::size_t n = w.front().u.size();
  std::vector<double> a(2 * n * w.size());
  for (std::size_t j = 0; j < w.size(); ++j) {
    if (w[j].u.size() != n || w[j].v.size() != n) throw InvalidInput("vectors", ": must all have N entries in u and v");
    for (std::size_t i = 0; i < n; ++i) {
      a[j * 2 * n + i] = w[j].u[i];
      a[j * 2 * n + n + i] = t * w[j].v[i];
    }
  }
  return a;
}

void check_clv_config(const CovariantVectorsConfig& c, std::size_t beads, const std::vector<std::uint64_t>& samples) {
  if (c.vectors < 1 || c.vectors > 2 * beads)
    throw InvalidInput("vectors", " " + std::to_string(c.vectors) + ": between 1 and 2N = " + std::to_string(2 * beads));
  if (c.orthonormalize_every < 1) throw InvalidInput("orthonormalize_every", ": at least 1 step");
  if (!(c.time_unit > 0) || !std::isfinite(c.time_unit)) throw InvalidInput("time_unit", ": must be finite and > 0");
  if (!(c.memory_limit >= 0) || !std::isfinite(c.memory_limit))
    throw InvalidInput("memory_limit", ": must be finite and ≥ 0 (0: half of what the process may use)");
  if (samples.empty()) throw InvalidInput("sample_steps", ": at least one sample");
  if (!std::is_sorted(samples.begin(), samples.end())) throw InvalidInput("sample_steps", ": must be sorted");
}

// An upper bound of what the run keeps, checked before it starts: the packed R's (one per
// orthonormalize_every steps from the window's start, one more at each advance's end), and per
// sample the Q, the orbit and the CLVs.
double clv_bytes(const CovariantVectorsConfig& c, std::size_t beads, const std::vector<std::uint64_t>& samples) {
  const double k = static_cast<double>(c.vectors), n = static_cast<double>(beads);
  const double s = static_cast<double>(samples.size());
  const double steps = static_cast<double>(samples.back()) + static_cast<double>(c.backward_transient);
  const double factors = std::floor(steps / static_cast<double>(c.orthonormalize_every)) + s + 1;
  return 8 * (factors * k * (k + 1) / 2 + s * (2 * n * k * 2 + 2 * n + 3 * k));
}

}  // namespace

double smallest_subspace_angle(const std::vector<State>& a, const std::vector<State>& b, double time_unit) {
  if (!(time_unit > 0) || !std::isfinite(time_unit)) throw InvalidInput("time_unit", ": must be finite and > 0");
  std::vector<double> x = clv_columns(a, time_unit), y = clv_columns(b, time_unit);
  const std::size_t rows = 2 * a.front().u.size();
  if (2 * b.front().u.size() != rows) throw InvalidInput("vectors", ": both sets must have N entries in u and v");
  if (a.size() > rows || b.size() > rows) throw InvalidInput("vectors", ": at most 2N vectors in a set");
  double angle = 0;
  if (!clv_orthonormalize(x, rows, a.size()) || !clv_smallest_angle(x, rows, a.size(), y, b.size(), angle))
    throw InvalidInput("vectors", ": each set must be finite and linearly independent");
  return angle;
}

CovariantMemory covariant_memory(const CovariantVectorsConfig& config, std::size_t beads,
                                 const std::vector<std::uint64_t>& sample_steps) {
  if (sample_steps.empty()) throw InvalidInput("sample_steps", ": at least one sample");
  CovariantMemory m{.bytes = clv_bytes(config, beads, sample_steps),
                    .limit = config.memory_limit,
                    .source = "memory_limit"};
  if (m.limit == 0) {
    const detail::MemoryLimit memory = detail::memory_limit();
    m.limit = memory.bytes / 2;
    m.source = "half of " + memory.source;
  }
  return m;
}

CovariantVectors covariant_vectors(const ForceLaw& law, const Chain& chain, const SplittingScheme& scheme,
                                   double time_step, const State& initial, const CovariantVectorsConfig& config,
                                   const std::vector<std::uint64_t>& sample_steps) {
  const std::size_t n = chain.size(), k = config.vectors, rows = 2 * n, packed = k * (k + 1) / 2;
  check_clv_config(config, n, sample_steps);
  // Refuse what cannot fit now, not hours in with bad_alloc (as the energy map does): half of
  // what this process may use leaves room for the run and the caller's copies.
  const CovariantMemory memory = covariant_memory(config, n, sample_steps);
  if (!memory.fits()) {
    char text[400];
    std::snprintf(text, sizeof text,
                  " up to %llu with `backward_transient` %zu: the stored factors and vectors need %.3g bytes, more "
                  "than the %.3g allowed (%s); take a shorter window, fewer vectors or a longer "
                  "`orthonormalize_every`",
                  static_cast<unsigned long long>(sample_steps.back()), config.backward_transient, memory.bytes,
                  memory.limit, memory.source.c_str());
    throw InvalidInput("sample_steps", text);
  }

  // Forward: the Lyapunov spectrum's run, its R's recorded from the window's start on.
  LyapunovSpectrum forward(law, chain, scheme, time_step, initial,
                           {.vectors = k,
                            .orthonormalize_every = config.orthonormalize_every,
                            .time_unit = config.time_unit,
                            .seed = config.seed});
  if (config.forward_transient > 0) forward.advance(config.forward_transient);
  std::vector<double> factors;  // R_r packed by columns: R_r maps the Q of point r to point r + 1
  factors.reserve(
      static_cast<std::size_t>(std::floor(static_cast<double>(sample_steps.back() + config.backward_transient) /
                                          static_cast<double>(config.orthonormalize_every))) *
      packed);
  forward.record_factors([&factors, k](std::span<const double> r) {
    for (std::size_t j = 0; j < k; ++j)
      for (std::size_t i = 0; i <= j; ++i) factors.push_back(r[j * k + i]);
  });
  const std::size_t samples = sample_steps.size();
  CovariantVectors out;
  std::vector<std::vector<double>> q(samples);
  std::vector<std::size_t> point(samples);  // the number of R's before each sample
  std::uint64_t done = 0;
  for (std::size_t s = 0; s < samples; ++s) {
    if (sample_steps[s] > done) forward.advance(static_cast<std::size_t>(sample_steps[s] - done));
    done = sample_steps[s];
    out.steps.push_back(config.forward_transient + done);
    out.time.push_back(forward.time());
    out.orbit.push_back(forward.state());
    q[s] = clv_columns(forward.vectors(), config.time_unit);
    point[s] = factors.size() / packed;
  }
  if (config.backward_transient > 0) forward.advance(config.backward_transient);
  const std::size_t total = factors.size() / packed;

  // Backward: C ← R⁻¹ C from a random upper-triangular C (random_deviation_vectors' generator, on
  // a seed of its own), columns scaled to unit length; −ln of a column's norm is CLV_i's forward
  // stretch over that interval.
  std::vector<double> c(k * k, 0.0), r(k * k, 0.0);
  {
    const std::vector<State> random = detail::random_deviation_vectors(k, k, ~config.seed, 1.0);
    for (std::size_t j = 0; j < k; ++j)
      for (std::size_t i = 0; i <= j; ++i) c[j * k + i] = random[j].u[i];
  }
  std::vector<double> norms(k), growth(k, 0.0), diagonal(k, 0.0);
  const auto normalize = [&] {
    for (std::size_t j = 0; j < k; ++j) {
      double s = 0;
      for (std::size_t i = 0; i <= j; ++i) s += c[j * k + i] * c[j * k + i];
      norms[j] = std::sqrt(s);
      if (!(norms[j] > 0) || !std::isfinite(norms[j]))
        throw NumericalError("covariant vectors: column " + std::to_string(j + 1) + " of C became " +
                             (std::isfinite(norms[j]) ? "zero" : "non-finite"));
      for (std::size_t i = 0; i <= j; ++i) c[j * k + i] /= norms[j];
    }
  };
  normalize();
  out.vectors.resize(samples);
  out.split_angles.resize(samples);
  out.participation.resize(samples);
  out.centre.resize(samples);
  std::vector<double> identity(k * k, 0.0);
  for (std::size_t i = 0; i < k; ++i) identity[i * k + i] = 1;
  // The outputs of every sample at the current point: CLV_i = Q C_i, its localization, the angles.
  // The samples' points do not decrease: walk them from the last, once.
  std::size_t pending = samples;
  const auto emit = [&](std::size_t now) {
    for (; pending > 0 && point[pending - 1] == now; --pending) {
      const std::size_t s = pending - 1;
      std::vector<State>& clv = out.vectors[s];
      clv.assign(k, State(n));
      out.participation[s].assign(k, 0.0);
      out.centre[s].assign(k, 0.0);
      std::vector<double> x(rows);
      for (std::size_t i = 0; i < k; ++i) {
        std::fill(x.begin(), x.end(), 0.0);
        for (std::size_t l = 0; l <= i; ++l)
          for (std::size_t e = 0; e < rows; ++e) x[e] += q[s][l * rows + e] * c[i * k + l];
        double norm = 0;
        for (double e : x) norm += e * e;
        double inverse_participation = 0, centre = 0;
        for (std::size_t b = 0; b < n; ++b) {
          const double p = (x[b] * x[b] + x[n + b] * x[n + b]) / norm;
          inverse_participation += p * p;
          centre += static_cast<double>(b) * p;
        }
        out.participation[s][i] = 1 / inverse_participation;
        out.centre[s][i] = centre;
        norm = std::sqrt(norm);
        for (std::size_t b = 0; b < n; ++b) {
          clv[i].u[b] = x[b] / norm;
          clv[i].v[b] = x[n + b] / norm / config.time_unit;
        }
      }
      // In Q's coordinates span(CLV_1 … CLV_j) is that of the first j unit vectors (C is upper
      // triangular), and Q is orthonormal: the angles are C's.
      out.split_angles[s].assign(k > 0 ? k - 1 : 0, 0.0);
      for (std::size_t j = 1; j < k; ++j) {
        std::vector<double> first(identity.begin(), identity.begin() + static_cast<std::ptrdiff_t>(j * k));
        std::vector<double> rest(c.begin() + static_cast<std::ptrdiff_t>(j * k), c.end());
        if (!clv_smallest_angle(first, k, j, rest, k - j, out.split_angles[s][j - 1]))
          throw NumericalError("covariant vectors: CLVs " + std::to_string(j + 1) + " … " + std::to_string(k) +
                               " became dependent");
      }
    }
  };
  emit(total);
  const int kk = static_cast<int>(k);
  const double one = 1;
  for (std::size_t p = total; p-- > point.front();) {
    for (std::size_t j = 0; j < k; ++j)
      for (std::size_t i = 0; i <= j; ++i) r[j * k + i] = factors[p * packed + j * (j + 1) / 2 + i];
    dtrsm_("L", "U", "N", "N", &kk, &kk, &one, r.data(), &kk, c.data(), &kk, 1, 1, 1, 1);
    normalize();
    if (p + 1 <= point.back())  // interval p lies in the window
      for (std::size_t j = 0; j < k; ++j) {
        growth[j] -= std::log(norms[j]);
        diagonal[j] += std::log(std::abs(r[j * k + j]));
      }
    emit(p);
  }
  const double window = out.time.back() - out.time.front();
  out.growth_rates.assign(k, 0.0);
  out.exponents.assign(k, 0.0);
  if (window > 0)
    for (std::size_t j = 0; j < k; ++j) {
      out.growth_rates[j] = growth[j] / window;
      out.exponents[j] = diagonal[j] / window;
    }
  out.stored_bytes = 8 * (static_cast<double>(factors.size()) +
                          static_cast<double>(samples) * static_cast<double>(2 * rows * k + rows + 3 * k));
  return out;
}

}  // namespace granular
