#pragma once
// The files of a spreading run or ensemble (the `spreading` tool's contract, DESIGN.md): one
// writer per file, so that any program writes them exactly as the tool does.
#include <cstddef>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>  // SpreadingDescription holds json values

#include "granular/case/spreading_run.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/hdf5_file.hpp"
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
/// t,site,share: the deviation vector's distribution along the chain (with the tangent map).
void write_deviation_csv(std::ostream& out, const SpreadingResult& run);
/// t, lambda_1 … lambda_k [1/s], then with k ≥ 2 gali_2 … gali_k and sali: the run's Lyapunov
/// spectrum and alignment indices (run.lyapunov) at its sample times.
void write_lyapunov_csv(std::ostream& out, const SpreadingResult& run);
/// The energy map as HDF5, whole or not at all: datasets energy [time][column] [J], t [s] and
/// site (the first bead of each column, from 1; `stride` beads per column). Written under its
/// temporary name and returned uncommitted, as AtomicFile is (Hdf5File::commit puts it in place).
std::unique_ptr<Hdf5File> write_energy_map(const std::string& path, const SpreadingResult& run, std::size_t stride);
/// The same layout of any chain's map, the one writer of both: `energy` rows × columns (row k at t[k]),
/// t and site (the first site of each column, from 1; `stride` sites per column), in the caller's units.
std::unique_ptr<Hdf5File> write_energy_map(const std::string& path, const std::vector<double>& t,
                                           const std::vector<double>& energy, std::size_t columns, std::size_t stride);

/// The CLVs of a run (run.covariant) as rows, sample by sample and in each CLV by CLV: row s k + i is
/// CLV_{i+1} at sample s, δu_1..δu_N [dimensionless] then δv_1..δv_N [1/s] (what PREFIX-clv.h5 holds).
std::vector<double> covariant_rows(const CovariantVectors& clv);
/// PREFIX-clv.h5, whole or not at all: datasets t [s] (samples), vectors (covariant_rows: samples·k rows of
/// 2N), growth_rates and exponents [1/s] (k), with k ≥ 2 split_angles [rad] (samples × (k − 1)),
/// participation [beads] and centre [bead index, from 0] (samples × k); the units and layout as
/// attributes. Returned uncommitted, as write_energy_map's.
std::unique_ptr<Hdf5File> write_covariant_vectors(const std::string& path, const SpreadingResult& run,
                                                  const SpreadingRunConfig& config);
/// The "covariant_vectors" entry of a run's JSON: k, the `seed` of the starting vectors, the norm's t_unit, the
/// transients, the samples, the growth rates and exponents [1/s], stored_bytes, and its `file` (none when empty).
nlohmann::json describe_covariant(const SpreadingResult& run, const SpreadingRunConfig& config, const std::string& file);

/// The "lyapunov_spectrum" entry of a run's JSON: the vectors k, the `seed` of their random
/// starting vectors, λ_j, GALI_j and SALI at T, and its `file` (none when empty).
nlohmann::json describe_lyapunov(const SpreadingResult& run, const SpreadingRunConfig& config, const std::string& file);

/// The "run" entry of a run's JSON: the realization, initial energy, worst energy error, steps,
/// bond updates, integration time, final active window (beads from 1), wall energy; the energy
/// dissipated by T [J] with damping and X1(T) [1/s] with the tangent map.
nlohmann::json describe_run(const SpreadingResult& run, const nlohmann::json& realization);

/// Where the files of one spreading run or ensemble go ("" where one is not written).
struct SpreadingPaths {
  std::string csv, json, sem, profile, forces, checkpoint;   ///< under the prefix (spreading_paths)
  std::string final_state, energy_map, spectrum, deviation;  ///< named by the user, one realization each
  std::string lyapunov;                                      ///< PREFIX-lyapunov.csv, one realization
  std::string covariant;                                     ///< PREFIX-clv.h5, one realization
  /// Every path, to be checked before the run (io/output_paths.hpp, check_outputs).
  std::vector<std::string> all() const;
};

/// The files under `prefix`: PREFIX.csv and PREFIX.json; with `ensemble` PREFIX-sem.csv (standard
/// errors) and PREFIX.checkpoint; with `profile` PREFIX-profile.csv; with `forces` PREFIX-forces.csv;
/// with `lyapunov` PREFIX-lyapunov.csv; with `covariant` PREFIX-clv.h5.
SpreadingPaths spreading_paths(const std::string& prefix, bool ensemble, bool profile, bool forces,
                               bool lyapunov = false, bool covariant = false);

/// Writes every file of `paths` but the JSON and the checkpoint: the means of `ensemble` where
/// there is one (the curves, their standard errors, the profile), else those of `run`, and what
/// only one realization has (forces at config.forces.sites, final state, g(ν), energy map with
/// config.energy_map->stride, deviation vector, Lyapunov spectrum, CLVs) from `run`. Every file, the HDF5 map included,
/// is returned under its temporary name, to be committed after the JSON (never an output without its metadata).
struct SpreadingFiles {
  std::vector<std::unique_ptr<AtomicFile>> text;  ///< the CSVs
  std::unique_ptr<Hdf5File> energy_map;           ///< null without a map
  std::unique_ptr<Hdf5File> covariant;            ///< null without the CLVs
  /// Puts every file in place (after the JSON); throws IoError.
  void commit();
};
SpreadingFiles write_spreading_files(const SpreadingPaths& paths, const SpreadingResult& run,
                                     const TransportSummary* ensemble, const SpreadingRunConfig& config);

/// What a user must read after the run: the ensemble's warnings, the run's (none from a run not
/// made), the notes on the case.
std::vector<std::string> spreading_notes(const TransportCase& c, const SpreadingResult& run,
                                         const TransportSummary* ensemble);

/// The "parameters" entry of the JSON: describe(c), the chain as built (`chain`), and what the kick
/// used: beta_used [m/s] for a velocity kick (unless an ensemble matched it chain by chain), mode_used.
nlohmann::json describe_parameters(const TransportCase& c, const nlohmann::json& chain, const KickedChain& kicked,
                                   bool ensemble);

/// The "ensemble" entry of the JSON: realizations averaged, threads as requested (0: every
/// core), MPI ranks, the worst relative energy error, how many realizations reached the walls,
/// and the failed realizations left out (failed_excluded).
nlohmann::json describe_ensemble(const TransportSummary& summary, int threads);

/// The "spectrum" entry of the JSON for g(ν): of (displacement | velocity) and samples.
nlohmann::json describe_spectral_density(const SpectralDensityObserver::Settings& settings);

/// The exponents' entries of the JSON (gamma, gamma_err, gamma_real_err, eta, eta_err,
/// eta_real_err, power_law, exponents): to_json(exponents, shown), each null when none were fitted.
nlohmann::json describe_exponents(const std::optional<TransportExponents>& exponents, SpreadCentre shown);

/// What the spreading tool's JSON and granular.spreading / granular.transport's metadata say of a
/// run, in one place for both front ends.
struct SpreadingDescription {
  const TransportCase& c;
  const nlohmann::json& chain;  ///< the chain as built (the selected chain's description)
  const KickedChain& kicked;    ///< the kick of the run, or of realization 0 of an ensemble
  const nlohmann::json& step_rule;
  const std::optional<TransportExponents>& exponents;
  const SpreadingResult* run = nullptr;        ///< one realization run, or null (an ensemble alone)
  nlohmann::json realization{};                ///< with `run`: its realization number
  const TransportSummary* ensemble = nullptr;  ///< the ensemble's means, or null
  int threads = 0;                             ///< with `ensemble`: the threads asked for
  nlohmann::json resumed{};                    ///< resumed_code of its checkpoint, or null
  const SpreadingPaths* paths = nullptr;       ///< the files named in the entries; null: none (Python)
};
/// parameters, seed, time_step_rule, the exponents' entries, with an ensemble `ensemble` (and
/// resumed_checkpoint when resumed), with a run `run` and the entries of what it recorded
/// (spectrum, lyapunov_spectrum, covariant_vectors), each with its file where `paths` names one.
nlohmann::json describe_spreading(const SpreadingDescription& d);

}  // namespace granular
