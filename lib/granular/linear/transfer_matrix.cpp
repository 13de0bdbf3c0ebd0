#include "granular/linear/transfer_matrix.hpp"

#include <omp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <exception>
#include <mutex>
#include <numbers>
#include <string>

#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

constexpr std::size_t piece_beads = 1024;     // beads read from the source at once (40 kB of coefficients)
constexpr std::size_t renormalize_every = 8;  // growth per bead stays far below 1e38 for any sane frequency

/// a·b + c with one rounding where the CPU has FMA (built with -march=native), else with two:
/// std::fma without the instruction is a library call, ~50× slower. Either way every lane,
/// vector or scalar, rounds alike within one build.
inline double multiply_add(double a, double b, double c) {
#ifdef __FMA__
  return std::fma(a, b, c);
#else
  return a * b + c;  // -ffp-contract=off: not fused behind our back
#endif
}

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
/// overflowed lane stays non-finite (and is reported) instead of wrapping around. Written with
/// plain comparisons (not std::fmax/std::clamp, which GCC 12 does not vectorize here: that made
/// the whole walk 2.5× slower).
template <std::size_t W>
inline void renormalize(Lanes<W>& s) {
  for (std::size_t j = 0; j < W; ++j) {
    const double x = std::fabs(s.u[j]), y = std::fabs(s.up[j]);
    const double big = x > y ? x : y;
    std::int64_t e = static_cast<std::int64_t>((std::bit_cast<std::uint64_t>(big) >> 52) & 0x7ff);
    e = e < 1 ? 1 : e;
    e = e > 2045 ? 2045 : e;
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
void sweep(std::size_t count, const double* alpha, const double* beta, const double* gamma, Lanes<W>& state) {
  Lanes<W> s = state;  // a local copy the compiler keeps in registers across beads
  for (std::size_t i = 0; i < count;) {
    const std::size_t stop = std::min(count, i + renormalize_every);
    for (; i < stop; ++i) {
      const double a = alpha[i], b = beta[i], g = gamma[i];
      for (std::size_t j = 0; j < W; ++j) {
        const double c = multiply_add(-b, s.w2[j], a);
        const double next = multiply_add(c, s.u[j], -(g * s.up[j]));
        s.nodes[j] +=
            static_cast<std::int64_t>((std::bit_cast<std::uint64_t>(next) ^ std::bit_cast<std::uint64_t>(s.u[j])) >> 63);
        s.up[j] = s.u[j];
        s.u[j] = next;
      }
    }
    renormalize(s);
  }
  state = s;
}

/// ln ‖(u_{n+1}, u_n)‖ of lane j right after a renormalization.
template <std::size_t W>
double log_norm(const Lanes<W>& s, std::size_t j) {
  return static_cast<double>(s.exponent[j]) * std::numbers::ln2 + 0.5 * std::log(s.u[j] * s.u[j] + s.up[j] * s.up[j]);
}

/// One block: frequencies first … first+count−1 (count ≤ W), one per lane.
template <std::size_t W>
struct Block {
  std::size_t first = 0, count = 0;
  Lanes<W> lanes;
  std::vector<double> rate;    // segment exponents, segment-major
  std::vector<double> logged;  // ln ‖(u_{n+1}, u_n)‖ at the last segment end
};

/// The blocks `first_block`, `first_block + stride`, … walk the chain together: each piece of
/// the chain is read (and its coefficients computed) once and swept by every block while it is
/// in cache, so a thread generates a streamed chain once however many frequencies it holds.
template <std::size_t W>
void run_blocks(const BeadSource& chain, const std::vector<double>& omega2, std::size_t first_block, std::size_t stride,
                std::size_t segments, const TransferMatrixConfig& config, TransferMatrixScan& out) {
  const std::size_t n = chain.size(), f = omega2.size();
  std::vector<Block<W>> blocks;
  std::size_t lanes_used = 0;
  for (std::size_t b = first_block; b * W < f; b += stride) {
    Block<W>& block = blocks.emplace_back();
    block.first = b * W;
    block.count = std::min(W, f - block.first);
    block.rate.assign(segments * W, 0.0);
    block.logged.assign(W, 0.0);
    for (std::size_t j = 0; j < W; ++j) {
      block.lanes.w2[j] = omega2[block.first + std::min(j, block.count - 1)];  // spare lanes repeat the last
      block.lanes.u[j] = 1;                                                    // u_1
      block.lanes.up[j] = 0;                                                   // u_0, the wall
      block.lanes.exponent[j] = 0;
      block.lanes.nodes[j] = 0;
    }
    lanes_used += block.count;
  }
  if (blocks.empty()) return;
  std::vector<double> mass(piece_beads), stiffness(piece_beads + 1), alpha(piece_beads), beta(piece_beads),
      gamma(piece_beads);
  const bool grounded = chain.grounded();
  std::vector<double> onsite(grounded ? piece_beads : 0);
  for (std::size_t seg = 0; seg < segments; ++seg) {
    const std::size_t begin = n * seg / segments, end = n * (seg + 1) / segments;
    for (std::size_t p = begin; p < end; p += piece_beads) {
      const std::size_t m = std::min(piece_beads, end - p);
      chain.read(p, m, mass.data(), stiffness.data());
      if (grounded) chain.read_onsite(p, m, onsite.data());
      for (std::size_t i = 0; i < m; ++i) {
        const double inverse = 1.0 / stiffness[i + 1];
        // An on-site spring adds k_n to the diagonal of K: (B_n + B_{n+1} + k_n − m_n ω²) u_n.
        alpha[i] = (grounded ? stiffness[i] + stiffness[i + 1] + onsite[i] : stiffness[i] + stiffness[i + 1]) * inverse;
        beta[i] = mass[i] * inverse;
        gamma[i] = stiffness[i] * inverse;
      }
      for (Block<W>& block : blocks) sweep(m, alpha.data(), beta.data(), gamma.data(), block.lanes);
    }
    for (Block<W>& block : blocks)
      for (std::size_t j = 0; j < W; ++j) {
        const double total = log_norm(block.lanes, j);
        block.rate[seg * W + j] = (total - block.logged[j]) / static_cast<double>(end - begin);
        block.logged[j] = total;
      }
    if (config.progress) config.progress((end - begin) * lanes_used);
  }
  for (const Block<W>& block : blocks)
    for (std::size_t j = 0; j < block.count; ++j) {
      const std::size_t k = block.first + j;
      if (!std::isfinite(block.logged[j]))
        throw NumericalError("frequencies: the transfer-matrix recursion overflowed at " +
                             format_number(out.frequency_khz[k]) + " kHz (far above the bands?)");
      out.lyapunov[k] = block.logged[j] / static_cast<double>(n);
      double mean = 0, sum2 = 0;
      for (std::size_t seg = 0; seg < segments; ++seg) mean += block.rate[seg * W + j];
      mean /= static_cast<double>(segments);
      for (std::size_t seg = 0; seg < segments; ++seg)
        sum2 += (block.rate[seg * W + j] - mean) * (block.rate[seg * W + j] - mean);
      const double sd = static_cast<double>(segments);
      out.lyapunov_error[k] = std::sqrt(sum2 / (sd * (sd - 1)));
      out.modes_below[k] = block.lanes.nodes[j];
    }
}

/// The lane width: the narrowest of 16, 32, 64 that gives every thread a block, so a short
/// list is not padded into one wide block and a long one walks the chain as few times as
/// possible. Not 8: GCC 12 leaves an 8-lane loop
/// scalar, 4× slower per lane than 16 lanes.
std::size_t lane_width(std::size_t frequencies, std::size_t threads) {
  const std::size_t per_thread = (frequencies + threads - 1) / threads;
  for (std::size_t w : {16u, 32u})
    if (per_thread <= w) return w;
  return 64;
}

}  // namespace

TransferMatrixScan transfer_matrix_scan(const BeadSource& chain, const std::vector<double>& frequency_khz,
                                        const TransferMatrixConfig& config) {
  if (frequency_khz.empty()) throw InvalidInput("frequencies", ": the list is empty");
  for (std::size_t k = 0; k < frequency_khz.size(); ++k)
    if (!std::isfinite(frequency_khz[k]) || frequency_khz[k] < 0)
      throw InvalidInput("frequencies", ": value " + std::to_string(k + 1) + " = " + format_number(frequency_khz[k]) +
                                            " kHz (must be finite and >= 0)");
  if (config.segments < 2) throw InvalidInput("segments", " " + std::to_string(config.segments) + ": must be >= 2");
  if (config.threads < 0) throw InvalidInput("threads", " " + std::to_string(config.threads) + ": must be >= 0");
  const std::size_t n = chain.size();
  if (n < 2) throw InvalidInput("N", " " + std::to_string(n) + ": a chain needs at least 2 beads");

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

  const int threads = config.threads > 0 ? config.threads : omp_get_max_threads();  // honours OMP_NUM_THREADS
  const std::size_t width = lane_width(f, static_cast<std::size_t>(threads));
  const std::size_t blocks = (f + width - 1) / width;
  const int workers = static_cast<int>(std::min<std::size_t>(blocks, static_cast<std::size_t>(threads)));
  std::exception_ptr failure;
  std::mutex failure_mutex;
  // Thread t takes blocks t, t + workers, …: a fixed split, and a lane's arithmetic does not
  // depend on it anyway.
#pragma omp parallel num_threads(workers)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const auto stride = static_cast<std::size_t>(omp_get_num_threads());
    try {
      switch (width) {
        case 16: run_blocks<16>(chain, omega2, t, stride, out.segments, config, out); break;
        case 32: run_blocks<32>(chain, omega2, t, stride, out.segments, config, out); break;
        default: run_blocks<64>(chain, omega2, t, stride, out.segments, config, out); break;
      }
    } catch (...) {
      std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  return out;
}

}  // namespace granular
