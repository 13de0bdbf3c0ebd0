#pragma once
// The files of an IPR map (the `ipr-map` tool's contract, DESIGN.md): its CSV in each of its
// three shapes and the JSON entries that describe it, so that the tool and Python write alike.
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/study/ipr_map.hpp"

namespace granular {

/// Every mode: disorder,q,xi,mode,freq_khz,ipr (means over realizations by mode number).
/// With bin_khz > 0: disorder,q,xi,freq_lo_khz,freq_hi_khz,modes,ipr (modes of all realizations
/// in the bin; empty bins: modes 0, ipr nan). With a selection: disorder,q,xi,realization,mode,
/// freq_khz,ipr (one row per selected mode of each realization).
void write_ipr_map_csv(std::ostream& out, const IprMapConfig& config, const std::vector<IprMapCell>& cells);

/// The map's JSON entries: parameters (disorder, xi, q, N, F0_N, R1_m, material, walls,
/// realizations, seed, threads, solver; beads for a distribution), averaging ("mode" or
/// "frequency-bin", with bin_khz) or selection (method, near_khz, count, window_khz: null when not
/// given), clustered (relative_gap, modes, fraction). `threads`: the worker threads used.
nlohmann::json describe_ipr_map(const IprMapConfig& config, const std::vector<IprMapCell>& cells, int threads);

}  // namespace granular
