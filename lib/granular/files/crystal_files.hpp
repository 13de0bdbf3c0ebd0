#pragma once
// The files of the `crystal` and `crystal-ipr-map` jobs (their CSV tables), so that the tool and Python write alike;
// the JSON is describe(case, result) (crystal/crystal_study.hpp).
#include <ostream>
#include <string>

#include <vector>

#include "granular/crystal/crystal_study.hpp"
#include "granular/study/crystal_ipr_map.hpp"

namespace granular {

/// mode,freq_khz,omega2,ipr: one row per computed mode by increasing ω² [1/s²] (mode counts from 1
/// among those computed; a negative ω², an unstable mode, has a negative frequency).
void write_crystal_csv(std::ostream& out, const CrystalResult& r);

/// mode,bead,x,y,ux,uy: each computed mode's displacement of every bead (reference centre x, y [m];
/// displacement u = M^{-1/2} w of the unit eigenvector w [kg^{-1/2}]). Needs the eigenvectors.
void write_crystal_modes_csv(std::ostream& out, const CrystalResult& r);

/// width,freq_lo_khz,freq_hi_khz,modes,ipr,ratio,ratios: the IPR map (study/crystal_ipr_map.hpp),
/// one row per disorder width and frequency bin [k W, (k + 1) W) of its cell; an empty bin has
/// modes 0 and ipr nan, a bin without level-spacing ratios ratios 0 and ratio nan.
void write_crystal_ipr_map_csv(std::ostream& out, const CrystalIprMapConfig& config,
                               const std::vector<CrystalIprMapCell>& cells);

/// D in raw little-endian arrays for another solver (tests/benchmarks/crystal_scipy.py):
/// PREFIX.row_start.u64 (2N + 1 offsets), PREFIX.column.u64, PREFIX.value.f64 [1/s²], written
/// atomically. Throws IoError when a file cannot be written.
void write_crystal_matrix(const std::string& prefix, const CrystalMatrix& d);

}  // namespace granular
