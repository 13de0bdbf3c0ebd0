#include "granular/linear/transfer_matrix.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <exception>
#include <mutex>
#include <numbers>
#include <string>

#include "granular/error.hpp"
#include "granular/io/number_format.hpp"

namespace granular {
namespace {

constexpr std::size_t piece_beads = 1024;    // beads read from the source at once (40 kB of coefficients)
constexpr std::size_t renormalize_every = 8;  // growth per bead stays far below 1e38 for any sane frequency

/// The recursion state of W frequencies, one per vector lane. u = u_{n+1}, up = u_n (after n
/// beads); the true values are u · 2^exponent.
template <std::size_t W>
struct Lanes {
  alignas(64) double w2[W];
  alignas(64) double u[W];
  alignas(64) double up[W];
  alignas(64) std::int64_t exponent[W];
  alignas(64) std::int64_t nodes[W];
};

/// Scales each lane by the power of two that brings max(|u|, |up|) into [1, 2): exact, so the
/// results do not depend on where it happens. The biased exponent is clamped so that an
/// overflowed lane stays non-finite (and is reported) instead of wrapping around.
template <std::size_t W>
inline void renormalize(Lanes<W>& s) {
  for (std::size_t j = 0; j < W; ++j) {
    const double big = std::fmax(std::fabs(s.u[j]), std::fabs(s.up[j]));
    std::int64_t e = static_cast<std::int64_t>((std::bit_cast<std::uint64_t>(big) >> 52) & 0x7ff);
    e = std::clamp<std::int64_t>(e, 1, 2045);
    const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(2046 - e) << 52);  // 2^(1023 − e)
    s.u[j] *= scale;
    s.up[j] *= scale;
    s.exponent[j] += e - 1023;
  }
}

/// `count` beads: coefficients α = (B_n + B_{n+1})/B_{n+1}, β = m_n/B_{n+1}, γ = B_n/B_{n+1},
/// so that u_{n+1} = (α − β ω²) u_n − γ u_{n−1}. The lane loop has no dependence between
/// lanes and a fixed trip count W, which the compiler turns into W/8 AVX-512 (or W/4 AVX2)
/// operations per step; the sign-change count is an integer xor of sign bits (branch-free,
/// and an exact zero counts consistently with the LDLᵀ pivots either way).
template <std::size_t W>
void sweep(std::size_t count, const double* alpha, const double* beta, const double* gamma, Lanes<W>& s) {
  for (std::size_t i = 0; i < count;) {
    const std::size_t stop = std::min(count, i + renormalize_every);
    for (; i < stop; ++i) {
      const double a = alpha[i], b = beta[i], g = gamma[i];
      for (std::size_t j = 0; j < W; ++j) {
        const double c = std::fma(-b, s.w2[j], a);
        const double next = std::fma(c, s.u[j], -(g * s.up[j]));
        s.nodes[j] += static_cast<std::int64_t>((std::bit_cast<std::uint64_t>(next) ^ std::bit_cast<std::uint64_t>(s.u[j])) >> 63);
        s.up[j] = s.u[j];
        s.u[j] = next;
      }
    }
    renormalize(s);
  }
}

/// ln ‖(u_{n+1}, u_n)‖ of lane j right after a renormalization.
template <std::size_t W>
double log_norm(const Lanes<W>& s, std::size_t j) {
  return static_cast<double>(s.exponent[j]) * std::numbers::ln2 + 0.5 * std::log(s.u[j] * s.u[j] + s.up[j] * s.up[j]);
}

/// Frequencies first … first+count−1 (count ≤ W) walk the whole chain together.
template <std::size_t W>
void run_block(const BeadSource& chain, const std::vector<double>& omega2, std::size_t first, std::size_t count,
               std::size_t segments, const TransferMatrixConfig& config, TransferMatrixScan& out) {
  const std::size_t n = chain.size();
  Lanes<W> s;
  for (std::size_t j = 0; j < W; ++j) {
    s.w2[j] = omega2[first + std::min(j, count - 1)];  // spare lanes repeat the last frequency
    s.u[j] = 1;                                           // u_1
    s.up[j] = 0;                                          // u_0, the wall
    s.exponent[j] = 0;
    s.nodes[j] = 0;
  }
  std::vector<double> mass(piece_beads), stiffness(piece_beads + 1), alpha(piece_beads), beta(piece_beads),
      gamma(piece_beads), rate(segments * W), logged(W, 0.0);
  for (std::size_t seg = 0; seg < segments; ++seg) {
    const std::size_t begin = n * seg / segments, end = n * (seg + 1) / segments;
    for (std::size_t p = begin; p < end; p += piece_beads) {
      const std::size_t m = std::min(piece_beads, end - p);
      chain.read(p, m, mass.data(), stiffness.data());
      for (std::size_t i = 0; i < m; ++i) {
        const double inverse = 1.0 / stiffness[i + 1];
        alpha[i] = (stiffness[i] + stiffness[i + 1]) * inverse;
        beta[i] = mass[i] * inverse;
        gamma[i] = stiffness[i] * inverse;
      }
      sweep(m, alpha.data(), beta.data(), gamma.data(), s);
    }
    for (std::size_t j = 0; j < W; ++j) {
      const double total = log_norm(s, j);
      rate[seg * W + j] = (total - logged[j]) / static_cast<double>(end - begin);
      logged[j] = total;
    }
    if (config.progress) config.progress((end - begin) * count);
  }
  for (std::size_t j = 0; j < count; ++j) {
    const std::size_t k = first + j;
    if (!std::isfinite(logged[j]))
      throw NumericalError("frequencies: the transfer-matrix recursion overflowed at " +
                           format_number(out.frequency_khz[k]) + " kHz (far above the bands?)");
    out.lyapunov[k] = logged[j] / static_cast<double>(n);
    double mean = 0, sum2 = 0;
    for (std::size_t seg = 0; seg < segments; ++seg) mean += rate[seg * W + j];
    mean /= static_cast<double>(segments);
    for (std::size_t seg = 0; seg < segments; ++seg) sum2 += (rate[seg * W + j] - mean) * (rate[seg * W + j] - mean);
    const double sd = static_cast<double>(segments);
    out.lyapunov_error[k] = std::sqrt(sum2 / (sd * (sd - 1)));
    out.modes_below[k] = s.nodes[j];
  }
}

/// The lane width: the narrowest of 8, 16, 32, 64 that gives every thread a block, so a short
/// list is not padded into one wide block and a long one walks the chain as few times as
/// possible (each block reads the whole chain once).
std::size_t lane_width(std::size_t frequencies, std::size_t threads) {
  const std::size_t per_thread = (frequencies + threads - 1) / threads;
  for (std::size_t w : {8u, 16u, 32u}) if (per_thread <= w) return w;
  return 64;
}

}  // namespace

TransferMatrixScan transfer_matrix_scan(const BeadSource& chain, const std::vector<double>& frequency_khz,
                                        const TransferMatrixConfig& config) {
  if (frequency_khz.empty()) throw InvalidInput("frequencies: the list is empty");
  for (std::size_t k = 0; k < frequency_khz.size(); ++k)
    if (!std::isfinite(frequency_khz[k]) || frequency_khz[k] < 0)
      throw InvalidInput("frequencies: value " + std::to_string(k + 1) + " = " + format_number(frequency_khz[k]) +
                         " kHz (must be finite and >= 0)");
  if (config.segments < 2) throw InvalidInput("segments = " + std::to_string(config.segments) + ": must be >= 2");
  if (config.threads < 0) throw InvalidInput("threads = " + std::to_string(config.threads) + ": must be >= 0");
  const std::size_t n = chain.size();
  if (n < 2) throw InvalidInput("N = " + std::to_string(n) + ": a chain needs at least 2 beads");

  const std::size_t f = frequency_khz.size();
  TransferMatrixScan out;
  out.frequency_khz = frequency_khz;
  out.lyapunov.assign(f, 0.0);
  out.lyapunov_error.assign(f, 0.0);
  out.modes_below.assign(f, 0);
  out.beads = n;
  out.segments = std::min(config.segments, n);
  std::vector<double> omega2(f);
  for (std::size_t k = 0; k < f; ++k) {
    const double omega = 2 * std::numbers::pi * 1e3 * frequency_khz[k];
    omega2[k] = omega * omega;
  }

  const int threads = config.threads > 0 ? config.threads : omp_get_num_procs();
  const std::size_t width = lane_width(f, static_cast<std::size_t>(threads));
  const long blocks = static_cast<long>((f + width - 1) / width);
  std::exception_ptr failure;
  std::mutex failure_mutex;
  std::atomic<bool> stop{false};
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (long b = 0; b < blocks; ++b) {
    if (stop.load(std::memory_order_relaxed)) continue;
    try {
      const std::size_t first = static_cast<std::size_t>(b) * width, count = std::min(width, f - first);
      switch (width) {
        case 8: run_block<8>(chain, omega2, first, count, out.segments, config, out); break;
        case 16: run_block<16>(chain, omega2, first, count, out.segments, config, out); break;
        case 32: run_block<32>(chain, omega2, first, count, out.segments, config, out); break;
        default: run_block<64>(chain, omega2, first, count, out.segments, config, out); break;
      }
    } catch (...) {
      std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      stop = true;
    }
  }
  if (failure) std::rethrow_exception(failure);
  return out;
}

}  // namespace granular
