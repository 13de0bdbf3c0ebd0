// Near-degenerate clusters are flagged per mode: a mode with another eigenvalue
// within cluster_relative_gap · max ω² has an IPR that depends on the basis chosen inside the
// cluster. A mirror-symmetric chain made of two identical halves has modes localized near the
// walls whose even and odd combinations are split only by tunnelling through the chain
// (~e^{-N/ℓ}): exactly such pairs. A generic random chain of the same size has none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "granular/linear/mode_ipr.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/named_chains.hpp"

namespace granular {
namespace {

/// Types of realization 0 of an Anderson chain of n/2 beads, then the same types reversed.
Chain mirror_chain(std::size_t n, double xi) {
  Configuration half = realization_configuration(Disorder::anderson, 0.5, n / 2, 7, 0);
  Configuration types = half;
  types.insert(types.end(), half.rbegin(), half.rend());
  return from_types(types, {.N = n, .xi = xi});
}

/// Flags computed here from the relative gaps of the LAPACK eigenvalues, independently of the library.
std::vector<std::uint8_t> flags_from_gaps(const std::vector<double>& omega2) {
  std::vector<std::uint8_t> flags(omega2.size(), 0);
  for (std::size_t k = 0; k + 1 < omega2.size(); ++k)
    if (omega2[k + 1] - omega2[k] < 1e-10 * omega2.back()) flags[k] = flags[k + 1] = 1;
  return flags;
}

TEST(ClusterFlags, MirrorChainPairsAreFlaggedByEveryMethod) {
  const DynamicalMatrix d = dynamical_matrix(mirror_chain(100, 0.3));
  const Spectrum lapack = spectrum(d, all_modes(), {.vectors = true});
  ASSERT_EQ(lapack.clustered.size(), lapack.size());
  EXPECT_EQ(lapack.clustered, flags_from_gaps(lapack.omega2));
  const auto flagged = std::count(lapack.clustered.begin(), lapack.clustered.end(), 1);
  EXPECT_GE(flagged, 2) << "the mirror chain should have at least one near-degenerate pair";
  EXPECT_EQ(spectrum(d, all_modes(), {.method = SpectrumMethod::fast}).clustered, lapack.clustered);
  const double top = lapack.freq_khz.back();
  for (SpectrumMethod m : {SpectrumMethod::lapack, SpectrumMethod::bisect}) {  // partial: by node counts
    const Spectrum window = spectrum(d, granular::window(0, top * 1.01), {.method = m});
    EXPECT_EQ(window.clustered, lapack.clustered) << to_string(m);
  }
  const Spectrum arpack = spectrum(d, granular::window(20, 60), {.method = SpectrumMethod::arpack});
  ASSERT_GT(arpack.size(), 0u);
  for (std::size_t j = 0; j < arpack.size(); ++j)
    EXPECT_EQ(arpack.clustered[j], lapack.clustered[arpack.mode[j] - 1]) << "arpack, mode " << arpack.mode[j];
  // Each flagged pair: its IPR really depends on the basis. Rotating the pair by 45° (an equally
  // valid basis of its subspace) changes the IPRs far beyond any solver's precision.
  for (std::size_t k = 0; k + 1 < lapack.size(); ++k) {
    if (!lapack.clustered[k] || !lapack.clustered[k + 1]) continue;
    const std::size_t n = d.size();
    std::vector<double> plus(n), minus(n);
    for (std::size_t i = 0; i < n; ++i) {
      plus[i] = (lapack.vector(k)[i] + lapack.vector(k + 1)[i]) / std::sqrt(2.0);
      minus[i] = (lapack.vector(k)[i] - lapack.vector(k + 1)[i]) / std::sqrt(2.0);
    }
    const double rotated = std::max(displacement_ipr(plus.data(), d.inverse_sqrt_mass.data(), n),
                                    displacement_ipr(minus.data(), d.inverse_sqrt_mass.data(), n));
    const double original = std::max(lapack.ipr[k], lapack.ipr[k + 1]);
    EXPECT_GT(std::fabs(rotated - original), 1e-3) << "pair at mode " << k + 1;
  }
  // The nearest selection around a flagged mode sees the cluster too.
  const auto first = static_cast<std::size_t>(std::find(lapack.clustered.begin(), lapack.clustered.end(), 1) -
                                              lapack.clustered.begin());
  const Spectrum near = spectrum(d, nearest(lapack.freq_khz[first], 1), {.method = SpectrumMethod::bisect});
  ASSERT_EQ(near.size(), 1u);
  EXPECT_EQ(near.clustered[0], 1);
}

TEST(ClusterFlags, AGenericChainHasNoFlaggedModes) {
  for (Disorder disorder : {Disorder::anderson, Disorder::rdm1, Disorder::rdm2}) {
    const DynamicalMatrix d = dynamical_matrix(random_chain(disorder, {.N = 100, .xi = 0.5}));
    const Spectrum all = spectrum(d);
    EXPECT_EQ(all.clustered, flags_from_gaps(all.omega2));
    EXPECT_EQ(std::count(all.clustered.begin(), all.clustered.end(), 1), 0) << to_string(disorder);
    const Spectrum near = spectrum(d, nearest(20, 10), {.method = SpectrumMethod::bisect});
    EXPECT_EQ(std::count(near.clustered.begin(), near.clustered.end(), 1), 0) << to_string(disorder);
  }
}

}  // namespace
}  // namespace granular
