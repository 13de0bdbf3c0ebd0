#pragma once
// How a spectrum is solved — the `spectrum` tool's solver options, the keywords of
// granular.spectrum and granular.SpectrumSolver — described once over SpectrumConfig itself
// (parameter_table.hpp), with its own defaults: the method and LAPACK driver as words, the Ritz
// tolerance and Krylov basis of arpack/slepc, bisect's lanes, and whether eigenvectors come back.
// validate(SpectrumConfig, ModeSelection) checks them together with the selection; errors name
// the row.
#include "granular/linear/spectrum.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

/// Each solver setting's meaning and units. `vectors` is Python's (the tool names a file instead).
const ParameterTable<SpectrumConfig>& spectrum_parameters();

}  // namespace granular
