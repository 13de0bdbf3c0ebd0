#pragma once
// Where a breather branch must stop: at a linear mode its frequency crosses, but only a mode that
// overlaps the breather. A breather resonates with a mode it shares beads with (an extended band
// mode, or a localized one under the breather); a mode localized far away (a quasiperiodic or
// disordered chain's, tens of beads off) has no amplitude where the breather is and is passed.
#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"

namespace granular {

/// The overlap from which a crossed mode stops the branch: 1 % (see mode_overlap).
inline constexpr double crossing_overlap = 0.01;

/// How much displacement mode φ (a column of `modes`, as M^{-1/2} times the eigenvector) shares the
/// beads of profile x [m]: Σ_n q_n |φ_n| / max |φ|, with q_n = m_n x_n² / Σ m x² the breather's
/// share of its (mass-weighted) norm on bead n. 1 when the mode peaks under the whole breather,
/// about its typical relative amplitude there for an extended mode, e^{-distance/ξ} for a mode
/// localized (length ξ) at a distance.
double mode_overlap(const Spectrum& modes, const DynamicalMatrix& d, std::size_t j, std::span<const double> x);

/// A linear mode between two points of a branch.
struct ModeCrossing {
  std::size_t mode = 0;    ///< 1…N by increasing frequency
  double freq_khz = 0;     ///< its frequency [kHz]
  double overlap = 0;      ///< mode_overlap with the last point's profile
  bool band_edge = false;  ///< the edge of a band entered from a gap or from above the spectrum
};

/// The first mode (from `from_khz` towards `to_khz`, both excluded) whose overlap with profile x is at
/// least crossing_overlap; none when every crossed mode lies elsewhere. `modes` holds every mode with
/// its vector.
std::optional<ModeCrossing> blocking_crossing(const Spectrum& modes, const DynamicalMatrix& d,
                                              std::span<const double> x, double from_khz, double to_khz);

/// The stop reason: "reached linear mode 57 at 7.1234 kHz, overlap 0.42 with the breather (>= 0.01; band edge)".
std::string describe(const ModeCrossing& crossing);

}  // namespace granular
