#pragma once
// The density of states of a chain from node counting (docs/physics.md, "Infinite chains"): the
// number of eigenfrequencies below f is the number of sign changes of the transfer-matrix
// recursion's solution (Dean's method; see transfer_matrix.hpp), exact for the finite chain
// and O(N) per frequency, with no eigen-solver and memory O(frequencies).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "granular/linear/transfer_matrix.hpp"
#include "granular/model/bead_source.hpp"

namespace granular {

/// Eigenfrequencies of the finite chain (fixed walls) below each frequency [kHz]: exact
/// integers for frequencies not within rounding of an eigenfrequency. `threads` as in
/// TransferMatrixConfig. (transfer_matrix_scan gives the same counts beside λ in one pass.)
std::vector<std::int64_t> count_modes_below(const BeadSource& chain, const std::vector<double>& frequency_khz,
                                            int threads = 0);

/// Integrated density of states [modes per bead]: counts / N.
std::vector<double> integrated_density_of_states(const std::vector<std::int64_t>& modes_below, std::size_t beads);

/// Density of states [modes per bead per kHz] by differencing the IDOS of neighbouring
/// frequencies: central (IDOS_{k+1} − IDOS_{k−1}) / (f_{k+1} − f_{k−1}) inside, one-sided at the
/// two ends. Frequencies must be strictly increasing (InvalidInput naming `frequencies`); with a
/// single frequency there is nothing to difference and the result is NaN.
std::vector<double> density_of_states(const std::vector<double>& frequency_khz, const std::vector<double>& idos);

}  // namespace granular
