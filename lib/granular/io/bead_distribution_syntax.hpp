#pragma once
// The text forms of a bead distribution (model/bead_distribution.hpp) that a user types:
//   k types        "R1:P1,R2:P2,…"       radius [m] : probability (or mass [kg] : probability)
//   polydisperse   "uniform:LO:HI"        radius uniform on [LO, HI] [m]
//                  "normal:MEAN:SD:MIN"   radius normal (MEAN, SD) truncated below at MIN [m]
// Read back and spelled again exactly (numbers in shortest round-trip form), so a run can print
// the text that gives its very distribution.
#include <string>

#include "granular/model/bead_distribution.hpp"

namespace granular {

/// k types "R1:P1,R2:P2,…" drawn by `rule` (anderson: each bead, rdm1: each dimer, rdm2: two
/// types as spins); with `by_mass` each R is the mass [kg] of a steel sphere instead of its
/// radius. Validated; InvalidInput names `name` as its parameter (what the user calls it: a
/// library name such as `types`, which a front end tells in its words), followed by the text.
BeadDistribution parse_bead_types(const std::string& text, bool by_mass, Disorder rule, const std::string& name);

/// Polydisperse radii "uniform:LO:HI" or "normal:MEAN:SD:MIN" [m]. Validated, messages as above.
BeadDistribution parse_polydisperse(const std::string& text, const std::string& name);

/// The text that reads back as `d`: "R1:P1,…" (radii) for k types — their rule is not part of
/// it —, "uniform:LO:HI" or "normal:MEAN:SD:MIN" for polydisperse radii.
std::string spell(const BeadDistribution& d);

}  // namespace granular
