#pragma once
// The outputs of one spreading run beyond its curves, as front ends take them — the `spreading`
// tool's options of its force series, energy map and spectrum with their sampling, the keywords
// of granular.spreading — turned into the observers of a TransportCase by one rule. Errors name
// the choice (`forces_at`, `map_samples`, `spectrum_of`); each front end tells it in its own
// words. Which files they go to is the tool's (study/spreading_files.hpp).
#include <string>
#include <vector>

#include "granular/parameter_table.hpp"
#include "granular/study/transport_study.hpp"

namespace granular {

struct SpreadingOutputChoices {
  std::vector<long> forces_at{};             ///< beads 1…N (counting from 1) whose force is recorded; none: no series
  long long force_samples = 1000;            ///< uniform times 0 … T of the force series (≥ 2)
  bool energy_map = false;                   ///< record E_n(t)
  long long map_samples = 500;               ///< its uniform times 0 … T (≥ 2)
  long long map_stride = 1;                  ///< beads summed into one of its columns (≥ 1)
  bool spectral_density = false;             ///< compute g(ν)
  long long spectrum_samples = 2000;         ///< uniform samples 0 … T of the series it transforms (≥ 2)
  std::string spectrum_of = "displacement";  ///< displacement (the paper's g) | velocity
};

/// Each choice's meaning (parameter_table.hpp); `forces_at` has a text form, a comma list of beads
/// (empty: none). `energy_map` and `spectral_density` ask for an output; a tool that names the
/// output's file instead (spreading's --energy-map FILE, --spectrum FILE) sets them itself.
const ParameterTable<SpreadingOutputChoices>& spreading_output_parameters();

/// Checks the choices and sets the observers they ask of c.dynamics (forces, energy_map,
/// spectrum); needs c.chain (its size, for `forces_at`). Every count is checked whether or not its
/// output is asked: 2 ≤ samples ≤ 1e8, 1 ≤ map_stride ≤ 1e8. Throws InvalidInput naming the choice.
void apply(const SpreadingOutputChoices& choices, TransportCase& c);

}  // namespace granular
