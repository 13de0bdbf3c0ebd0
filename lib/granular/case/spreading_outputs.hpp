#pragma once
// The outputs of one spreading run beyond its curves — the force series, the energy map and the
// spectral density with their sampling — described over the typed TransportCase itself: each row
// of spreading_output_parameters() reaches the observer settings of c.dynamics (forces, energy_map,
// spectrum), so the `spreading` tool binds its flags and granular.spreading its keywords straight
// to the case, with the observers' own defaults. Errors name the parameter (`forces_at`,
// `map_samples`, `spectrum_of`); each front end tells it in its own words. Which files they go to
// is the tool's (files/spreading_files.hpp).
#include "granular/case/transport_case.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

/// Each output's meaning; `forces_at` has a text form, a comma list of beads counting from 1 (empty:
/// none; also Python's attribute). `energy_map` and `spectral_density` ask for an output; a tool
/// that names the output's file instead (spreading's --energy-map FILE, --spectrum FILE) sets them.
const ParameterTable<TransportCase>& spreading_output_parameters();

/// Refuses an output parameter given without the output it takes effect with, a bead of
/// `forces_at` outside the chain (needs c.chain: its size), and a count out of range whether or not
/// its output is asked: 2 ≤ samples ≤ 1e8, 1 ≤ map_stride ≤ 1e8. Throws InvalidInput naming it.
/// validate(TransportCase) calls it.
void validate_outputs(const TransportCase& c);

}  // namespace granular
