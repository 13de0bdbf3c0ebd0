#pragma once
// Spectral density of N sampled series (docs/physics.md, "Nonlinear dynamics"): g(ν) = Σ_n |x̂_n(ν)|² / max_ν Σ_n |x̂_n(ν)|²,
// x̂_n the DFT of x_n over K uniform samples. The paper's x is the displacement u; the velocity
// is the other choice a run offers (observers.hpp, SpectrumSource). FFTW plans once per (N, K) —
// planning is where its cost and its only failure are — and the plan is executed on every call.
#include <cstddef>
#include <vector>

namespace granular {

class SpectralDensity {
 public:
  /// For `sites` series of `samples` (≥ 2) values each. Throws NumericalError if
  /// FFTW cannot plan. Planning is serialized by a lock, so threads may each own one.
  SpectralDensity(std::size_t sites, std::size_t samples);
  ~SpectralDensity();
  SpectralDensity(const SpectralDensity&) = delete;
  SpectralDensity& operator=(const SpectralDensity&) = delete;

  /// `rows`: samples × sites, row k = x(t_k), t_k = k·dt. Fills g for the K/2+1 frequencies
  /// ν_j = j / (K dt) (frequency(j) in kHz).
  void compute(const std::vector<double>& rows, std::vector<double>& g);
  double frequency_khz(std::size_t j, double dt) const {
    return static_cast<double>(j) / (static_cast<double>(samples_) * dt) / 1e3;
  }
  std::size_t frequencies() const { return samples_ / 2 + 1; }

 private:
  std::size_t sites_, samples_;
  double* in_ = nullptr;
  void* out_ = nullptr;   // fftw_complex*
  void* plan_ = nullptr;  // fftw_plan
};

}  // namespace granular
