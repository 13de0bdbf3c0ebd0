#include "granular/analysis/bootstrap.hpp"

#include <cmath>
#include <exception>
#include <mutex>
#include <string>

#include <Random123/philox.h>
#include <omp.h>

#include "granular/error.hpp"

namespace granular {
namespace {

// How many times each realization is drawn in resample b: R uniform indices from (seed, b).
void draw_counts(std::uint64_t seed, std::uint64_t b, std::size_t realizations, std::vector<std::uint32_t>& counts) {
  counts.assign(realizations, 0);
  r123::Philox4x64 generator;
  const r123::Philox4x64::key_type key{{seed, b}};
  std::uint64_t counter = 0;
  std::size_t drawn = 0;
  while (drawn < realizations) {
    const auto block = generator(r123::Philox4x64::ctr_type{{counter++, 0, 0, 0}}, key);
    for (int j = 0; j < 4 && drawn < realizations; ++j, ++drawn) {
      const double u = static_cast<double>(block[j] >> 11) * 0x1.0p-53;  // [0, 1)
      ++counts[static_cast<std::size_t>(u * static_cast<double>(realizations))];
    }
  }
}

}  // namespace

std::vector<double> bootstrap_standard_deviation(
    std::span<const double> rows, std::size_t width,
    const std::function<std::vector<double>(const std::vector<double>& mean)>& statistics,
    const BootstrapConfig& config) {
  if (width == 0 || rows.empty() || rows.size() % width != 0)
    throw InvalidInput("bootstrap: rows must hold a whole number (>= 1) of series of `width` values");
  if (config.resamples < 2) throw InvalidInput("bootstrap resamples: need at least 2");
  const std::size_t realizations = rows.size() / width;
  const std::size_t resamples = config.resamples;
  std::vector<std::vector<double>> results(resamples);
  std::exception_ptr failure;
  std::mutex failure_lock;
  const int threads = config.threads > 0 ? config.threads : omp_get_max_threads();
#pragma omp parallel num_threads(threads)
  {
    std::vector<std::uint32_t> counts;
    std::vector<double> mean(width);
#pragma omp for schedule(dynamic, 8)
    for (std::size_t b = 0; b < resamples; ++b) {
      try {
        {
          const std::lock_guard<std::mutex> lock(failure_lock);
          if (failure) continue;
        }
        draw_counts(config.seed, b, realizations, counts);
        std::fill(mean.begin(), mean.end(), 0.0);
        for (std::size_t r = 0; r < realizations; ++r) {  // index order: thread-count independent
          if (counts[r] == 0) continue;
          const double w = counts[r];
          const double* row = rows.data() + r * width;
          for (std::size_t i = 0; i < width; ++i) mean[i] += w * row[i];
        }
        for (double& m : mean) m /= static_cast<double>(realizations);
        results[b] = statistics(mean);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_lock);
        if (!failure) failure = std::current_exception();
      }
    }
  }
  if (failure) std::rethrow_exception(failure);
  const std::size_t k = results[0].size();
  std::vector<double> sd(k, 0.0);
  for (std::size_t j = 0; j < k; ++j) {
    // Shifted by the first resample's value, so that identical resamples give exactly 0.
    const double shift = results[0].at(j);
    double mean = 0;
    for (const auto& r : results) mean += r.at(j) - shift;
    mean /= static_cast<double>(resamples);
    double var = 0;
    for (const auto& r : results) var += (r[j] - shift - mean) * (r[j] - shift - mean);
    sd[j] = std::sqrt(var / static_cast<double>(resamples - 1));
  }
  return sd;
}

}  // namespace granular
