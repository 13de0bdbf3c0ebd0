#pragma once
// The files of a spectrum (the `spectrum` tool's contract, DESIGN.md): the CSV of modes, the JSON
// entries that describe the solve, the eigenvectors as HDF5 and the raw matrix dump — one writer
// each, so that the tool and Python write them alike (where the linear module meets the file
// formats: neither knows the other).
#include <memory>
#include <ostream>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "granular/io/hdf5_file.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/model/material.hpp"

namespace granular {

/// Writes `spectrum` and the matrix's m^{-1/2} to an HDF5 file that appears whole or not at all.
/// Datasets: /mode, /omega2 [1/s²], /freq_khz, /ipr, /residual (K each), /inverse_sqrt_mass (N),
/// /eigenvectors (K × N, row j = unit w of mode j; displacements v = w ⊙ inverse_sqrt_mass) when
/// the spectrum holds vectors; attribute "method". Written under its temporary name and returned
/// uncommitted, for RunMetadata::write to put in place after the JSON. Throws IoError.
std::unique_ptr<Hdf5File> write_spectrum_hdf5(const std::string& path, const Spectrum& spectrum,
                                              const DynamicalMatrix& matrix);

/// mode,freq_khz,ipr — and clustered (1 for a mode in a near-degenerate cluster) with `clusters`.
void write_spectrum_csv(std::ostream& out, const Spectrum& spectrum, bool clusters);

/// The dynamical matrix as raw little-endian doubles PREFIX.diag.f64 (N) and PREFIX.offdiag.f64
/// (N-1) [1/s²], each whole or not at all. Throws IoError.
void write_matrix_dump(const std::string& prefix, const DynamicalMatrix& matrix);

/// The "band_edges_khz" entry: f1, f2, fb1, fb2, fb3 [kHz].
nlohmann::json describe(const BandEdges& edges);
/// The band edges of a chain description with a size ratio (xi, R1_m, F0_N) of beads of
/// `material`, as describe(BandEdges) gives them; null for a chain without xi.
nlohmann::json band_edges_of(const nlohmann::json& chain, const Material& material);

/// What was asked of a spectrum solve (the method as the user named it).
struct SpectrumRequest {
  ModeSelection selection = all_modes();
  SpectrumConfig config{};
};

/// The spectrum's JSON entries: clustered (relative_gap, modes), method, solver (method that ran,
/// fallbacks; with a selection restarts, candidates, max_relative_residual, tolerance, mpi_ranks),
/// selection (near_khz and count, or window_khz), and, when `chain` (its description) is not null,
/// chain and — for a chain with xi under F0 > 0 — band_edges_khz.
nlohmann::json describe_spectrum(const Spectrum& spectrum, const SpectrumRequest& request, const nlohmann::json& chain,
                                 const Material& material);

}  // namespace granular
