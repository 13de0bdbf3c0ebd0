#include "granular/dynamics/spectral_density.hpp"

#include <algorithm>
#include <cstring>

#include <fftw3.h>

#include "granular/error.hpp"

namespace granular {

SpectralDensity::SpectralDensity(std::size_t sites, std::size_t samples) : sites_(sites), samples_(samples) {
  if (samples < 2 || sites < 1) throw InvalidInput("spectral density: needs >= 2 samples and >= 1 site");
  in_ = fftw_alloc_real(sites * samples);
  auto* out = fftw_alloc_complex(sites * (samples / 2 + 1));
  out_ = out;
  // Row-major samples × sites: series n starts at n (idist 1) and steps by `sites` (stride).
  const int n[] = {static_cast<int>(samples)};
  const int s = static_cast<int>(sites);
  plan_ = fftw_plan_many_dft_r2c(1, n, s, in_, nullptr, s, 1, out, nullptr, s, 1, FFTW_ESTIMATE);
  if (!in_ || !out || !plan_) {
    fftw_free(in_);
    fftw_free(out);
    throw NumericalError("FFTW could not plan a transform of " + std::to_string(samples) + " samples");
  }
}

SpectralDensity::~SpectralDensity() {
  fftw_destroy_plan(static_cast<fftw_plan>(plan_));
  fftw_free(in_);
  fftw_free(out_);
}

void SpectralDensity::compute(const std::vector<double>& rows, std::vector<double>& g) {
  if (rows.size() != sites_ * samples_) throw InvalidInput("spectral density: wrong number of samples");
  std::memcpy(in_, rows.data(), rows.size() * sizeof(double));
  fftw_execute(static_cast<fftw_plan>(plan_));
  const auto* out = static_cast<const fftw_complex*>(out_);
  g.assign(frequencies(), 0.0);
  for (std::size_t j = 0; j < frequencies(); ++j)
    for (std::size_t n = 0; n < sites_; ++n) {
      const fftw_complex& c = out[j * sites_ + n];
      g[j] += c[0] * c[0] + c[1] * c[1];
    }
  const double peak = *std::max_element(g.begin(), g.end());
  if (peak > 0)
    for (double& x : g) x /= peak;
}

}  // namespace granular
