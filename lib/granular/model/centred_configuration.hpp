#pragma once
// A chain drawn outward from its centre bead (N−1)/2, for runs whose N is sized from T
// (chain_length_rule.hpp): the beads within any distance of the centre are the same for every N,
// so a longer chain only adds beads the wave never reaches. The usual draw (disorder.hpp) runs
// from the left wall, so there changing N moves the centre through a different chain.
#include <cstdint>

#include "granular/model/disorder.hpp"

namespace granular {

/// N bead types of realization r of seed s, drawn from the centre bead c = (N−1)/2 outward. A
/// unit is a bead (h, A) or a dimer (RDM1, RDM2, read left to right as in sample_configuration):
/// right unit j (beads c + j·u …) is unit 2j of the usual draw of the stream, left unit j (the
/// beads just left of c − j·u) is unit 2j+1; a unit cut by a wall loses its outer bead. A pure
/// function of (s, r, disorder, q), with bead c + k the same for every N that holds it.
Configuration centred_configuration(Disorder disorder, double q, std::size_t n, std::uint64_t seed,
                                    std::uint64_t realization);

}  // namespace granular
