#pragma once
// Every mode of a small crystal and the statistics of its spectrum (docs/crystals.md, "Spectra"):
// frequencies, vector IPRs, the level-spacing ratio ⟨r⟩ and the density of states.
#include <cstddef>
#include <span>
#include <vector>

#include "granular/crystal/crystal_matrix.hpp"

namespace granular {

struct CrystalSpectrumConfig {
  bool vectors = false;  ///< also return the eigenvectors (8 (2N)² bytes)
};

/// Every mode, by increasing ω².
struct CrystalSpectrum {
  std::vector<double> omega2;   ///< eigenvalues ω² of D [1/s²], signed: < 0 for an unstable packing
  std::vector<double> freq_hz;  ///< f = sqrt(ω²)/2π [Hz]; −sqrt(−ω²)/2π for ω² < 0
  std::vector<double> ipr;      ///< vector IPR of each mode (vector_ipr), in [1/N, 1]
  /// 2N × size() unit eigenvectors w of D, column-major (mode k at [2N k, 2N (k+1))); empty unless asked.
  /// Displacements: (v_x, v_y) of bead b = m_b^{-1/2} (w_{2b}, w_{2b+1}).
  std::vector<double> vectors;
  std::size_t beads = 0;
  /// crystal_nearest_modes: max ‖D w − ω² w‖ / max |D_ij| over the modes returned; 0 for every mode.
  double max_residual = 0;
  std::size_t size() const { return omega2.size(); }
};

/// Every mode of D by dense LAPACK (dsyevd): 24 (2N)² bytes. Throws InvalidInput naming `N`, before
/// allocating, when its workspace exceeds LAPACK's 32-bit sizes (N > 16383) or the memory this
/// process may use; NumericalError when LAPACK fails.
CrystalSpectrum crystal_spectrum(const CrystalMatrix& d, const CrystalSpectrumConfig& config = {});

/// Inverse participation ratio of a vector mode, in displacement form as the chain's mode_ipr:
///     P = Σ_b |v_b|⁴ / (Σ_b |v_b|²)²,   |v_b|² = v_{b,x}² + v_{b,y}²,   v = M^{-1/2} w,
/// with w an eigenvector of D: 1 when one bead moves, 1/N for a plane wave of equal amplitudes.
/// Each bead counts once with both its components, so the IPR does not depend on the polarization
/// of a plane wave, nor on rotating the axes. Displacements rather than w: what an experiment sees,
/// and the chain's convention, so 2D and 1D IPRs compare. Scale-free.
double vector_ipr(std::span<const double> w, std::span<const double> inverse_sqrt_mass);

/// Mean level-spacing ratio (Oganesyan & Huse 2007): r_n = min(s_n, s_{n+1}) / max(s_n, s_{n+1}),
/// s_n = e_{n+1} − e_n of ascending levels, averaged over n. Needs no unfolding. Pairs of zero
/// spacings (exact degeneracies of a symmetric crystal) carry no statistics and are skipped.
/// Reference values: 2 ln 2 − 1 = 0.3863 for uncorrelated (Poisson) levels, 0.5307 for the GOE.
struct SpacingRatio {
  double mean = 0;        ///< ⟨r⟩ (NaN when count is 0)
  std::size_t count = 0;  ///< ratios averaged
};
/// ⟨r⟩ of ascending `levels` (any unit).
SpacingRatio spacing_ratio(std::span<const double> levels);
/// ⟨r⟩ of the frequencies in [lo_hz, hi_hz] [Hz]; throws InvalidInput naming `window` unless lo < hi.
SpacingRatio spacing_ratio(const CrystalSpectrum& spectrum, double lo_hz, double hi_hz);

/// Histogram of the frequencies: `bins` equal bins over [lo_hz, hi_hz].
struct FrequencyHistogram {
  std::vector<double> edges;        ///< bins + 1 edges [Hz]
  std::vector<std::size_t> counts;  ///< modes in [edge_k, edge_{k+1}) (the last bin includes hi)
  std::vector<double> density;      ///< counts / (modes · bin width) [1/Hz]: integrates to the fraction inside
};
/// Throws InvalidInput naming `bins` (< 1) or `window` (not lo < hi, or not finite).
FrequencyHistogram frequency_histogram(const CrystalSpectrum& spectrum, std::size_t bins, double lo_hz, double hi_hz);

}  // namespace granular
