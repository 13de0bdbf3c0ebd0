#pragma once
// Which modes a front end asks for — the `spectrum` and `ipr-map` tools' options, the keywords of
// granular.spectrum and granular.ipr_map — described once (parameter_table.hpp) and turned into a
// ModeSelection by one rule (choose_modes, linear/spectrum.hpp). Errors name the choice (`near`,
// `count`, `window`); each front end tells it in its own words.
#include <optional>
#include <utility>

#include "granular/linear/spectrum.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

struct ModeSelectionChoices {
  std::optional<double> near{};                       ///< target frequency [kHz] of the `count` nearest modes
  std::optional<long> count{};                        ///< how many modes nearest `near`
  std::optional<std::pair<double, double>> window{};  ///< every mode in [lo, hi] [kHz]
};

/// Each choice's meaning (parameter_table.hpp); `window` has a text form, "F1:F2" (empty: none),
/// and no field: front ends that take values (Python) set it as a pair.
const ParameterTable<ModeSelectionChoices>& mode_selection_parameters();

/// The modes the choices select: choose_modes(near, count, window) (linear/spectrum.hpp).
ModeSelection choose_modes(const ModeSelectionChoices& choices);

}  // namespace granular
