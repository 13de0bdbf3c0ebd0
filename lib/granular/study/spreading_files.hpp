#pragma once
// The files of a spreading run or ensemble (the `spreading` tool's contract, DESIGN.md): one
// writer per file, so that any program writes them exactly as the tool does.
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/dynamics/spreading.hpp"
#include "granular/study/transport_study.hpp"

namespace granular {

/// t,m2,ipr,energy_error,m2_centroid — m2 about the excited bead, m2_centroid about the energy
/// centroid [bead²] — of one run, or the ensemble means; then `dissipated` [J] with damping and
/// `mle` (X1 [1/s]) with the tangent map, when the run has them.
void write_spreading_csv(std::ostream& out, const SpreadingResult& run);
void write_spreading_csv(std::ostream& out, const TransportSummary& ensemble);
/// t,m2_se,ipr_se,energy_error_se,m2_centroid_se: standard errors of the ensemble means.
void write_standard_errors_csv(std::ostream& out, const TransportSummary& ensemble);
/// site,u,v,energy at T (beads from 1).
void write_final_state_csv(std::ostream& out, const SpreadingResult& run);
/// site,energy,force at T of one run; site,energy,energy_se of an ensemble.
void write_profile_csv(std::ostream& out, const SpreadingResult& run);
void write_profile_csv(std::ostream& out, const TransportSummary& ensemble);
/// t,site,force at the beads `sites` (0-based; written from 1).
void write_forces_csv(std::ostream& out, const SpreadingResult& run, const std::vector<std::size_t>& sites);
/// freq_khz,g.
void write_spectrum_csv(std::ostream& out, const SpreadingResult& run);
/// t,site,share: the deviation vector's distribution along the chain (spreading --mle).
void write_deviation_csv(std::ostream& out, const SpreadingResult& run);
/// The energy map as HDF5, whole or not at all: datasets energy [time][column] [J], t [s] and
/// site (the first bead of each column, from 1; `stride` beads per column).
void write_energy_map(const std::string& path, const SpreadingResult& run, std::size_t stride);

/// The "run" entry of a run's JSON: the realization, initial energy, worst energy error, steps,
/// bond updates, integration time, final active window (beads from 1), wall energy; the energy
/// dissipated by T [J] with damping and X1(T) [1/s] with the tangent map.
nlohmann::json describe_run(const SpreadingResult& run, const nlohmann::json& realization);

}  // namespace granular
