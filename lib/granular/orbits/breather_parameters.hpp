#pragma once
// The parameters of a breather branch, described over the typed BreatherBranchConfig itself: each
// row reaches its field (c.near_khz, c.shooting.tolerance, …), so the `breathers` tool binds its
// flags and granular.breathers its keywords straight to the config, with its own defaults, and
// validate(BreatherBranchConfig) checks them. Not rows: the chain (the chain options, a
// granular.Chain) and the seed profile (the tool reads --seed-file, Python takes an array).
#include "granular/orbits/breather_branch.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

/// Each parameter of a branch: meaning, units, where it lives, the enums as words (`law`, `scheme`,
/// `newton`, `floquet_method`, `continuation`). A frequency left unset (NaN) is none.
const ParameterTable<BreatherBranchConfig>& breather_parameters();

}  // namespace granular
