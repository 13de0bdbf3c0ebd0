#pragma once
// Spectral density of the displacements (SPEC §4): g(ν) = Σ_n |û_n(ν)|² / max_ν Σ_n |û_n(ν)|²,
// û_n the DFT of u_n over K uniform samples. FFTW plans once per (N, K) — planning is where
// its cost and its only failure are — and the plan is executed on every call.
#include <cstddef>
#include <vector>

namespace granular {

class SpectralDensity {
 public:
  /// For `sites` displacement series of `samples` (≥ 2) values each. Throws NumericalError if
  /// FFTW cannot plan. Not thread-safe to construct (FFTW planning is global).
  SpectralDensity(std::size_t sites, std::size_t samples);
  ~SpectralDensity();
  SpectralDensity(const SpectralDensity&) = delete;
  SpectralDensity& operator=(const SpectralDensity&) = delete;

  /// `rows`: samples × sites, row k = u(t_k), t_k = k·dt. Fills g for the K/2+1 frequencies
  /// ν_j = j / (K dt) (frequency(j) in kHz).
  void compute(const std::vector<double>& rows, std::vector<double>& g);
  double frequency_khz(std::size_t j, double dt) const {
    return static_cast<double>(j) / (static_cast<double>(samples_) * dt) / 1e3;
  }
  std::size_t frequencies() const { return samples_ / 2 + 1; }

 private:
  std::size_t sites_, samples_;
  double* in_ = nullptr;
  void* out_ = nullptr;  // fftw_complex*
  void* plan_ = nullptr;  // fftw_plan
};

}  // namespace granular
