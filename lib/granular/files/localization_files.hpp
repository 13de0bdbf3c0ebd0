#pragma once
// The files of a localization scan (the `localization` tool's contract, DESIGN.md): its CSV and
// the JSON entries that describe it, so that the tool and Python write alike.
#include <ostream>

#include <nlohmann/json_fwd.hpp>

#include "granular/case/chain_choices.hpp"
#include "granular/model/material.hpp"
#include "granular/study/localization_scan.hpp"

namespace granular {

/// The chain a localization scan takes unless told otherwise (the `localization` tool's chain
/// options and granular.localization's keywords): the paper's Anderson chain of 10⁶ beads, drawn a
/// piece at a time, so memory does not grow with N.
inline ChainChoices localization_chain() { return {.n = 1000000}; }
/// The frequencies it scans unless told otherwise [kHz]: 0 to 50 every 0.01 (the range syntax of
/// io/range_syntax.hpp), past the paper's chains' highest frequency.
inline constexpr const char* localization_frequencies = "0:50:0.01";

/// freq_khz,lyapunov,lyapunov_err,loc_length,idos,dos,resolved.
void write_localization_csv(std::ostream& out, const LocalizationScan& scan);

/// The scan's JSON entries: chain (its description), parameters (frequencies_khz as asked for —
/// the range text or the list —, frequency_count, segments, threads), columns (what each CSV
/// column is), resolved_rule (when loc_length is a measurement), and band_edges_khz for a chain with xi (beads of `material`).
nlohmann::json describe_localization(const LocalizationScan& scan, const nlohmann::json& chain,
                                     const nlohmann::json& frequencies, int threads, const Material& material);

}  // namespace granular
