#pragma once
// The files of the `crystal` job (its CSV tables), so that the tool and Python write alike; the
// JSON is describe(case, result) (crystal/crystal_study.hpp).
#include <ostream>

#include "granular/crystal/crystal_study.hpp"

namespace granular {

/// mode,freq_khz,omega2,ipr: one row per computed mode by increasing ω² [1/s²] (mode counts from 1
/// among those computed; a negative ω², an unstable mode, has a negative frequency).
void write_crystal_csv(std::ostream& out, const CrystalResult& r);

/// mode,bead,x,y,ux,uy: each computed mode's displacement of every bead (reference centre x, y [m];
/// displacement u = M^{-1/2} w of the unit eigenvector w [kg^{-1/2}]). Needs the eigenvectors.
void write_crystal_modes_csv(std::ostream& out, const CrystalResult& r);

}  // namespace granular
