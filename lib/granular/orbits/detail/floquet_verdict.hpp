#pragma once
// The verdict on a set of Floquet multipliers, one for both methods (floquet.hpp, "The +1 pair").
#include "granular/orbits/floquet.hpp"

namespace granular::detail {

/// From s.multipliers and s.complete: max_modulus without the phase/family pair (unit_pair),
/// stable (complete only), instability, growth_rate over `period` [s], tolerance and
/// unit_pair_distance.
void decide_floquet_verdict(FloquetSpectrum& s, double tolerance, double unit_pair_window, double period);

}  // namespace granular::detail
