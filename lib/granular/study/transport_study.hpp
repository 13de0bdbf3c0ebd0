#pragma once
// One cell of the paper's transport study (docs/physics.md, "Transport exponents"): the R
// realizations of a TransportCase (case/transport_case.hpp) integrated to T, averaged, and fitted.
// This is where the model (which chain), dynamics (how one realization evolves), ensemble (how
// many, where) and analysis (what the averages say) meet; none of them knows about the others.
//
// The mean m̃2 is taken about the excited bead (the paper's definition, the default) and about the
// energy centroid; both are fitted, both are reported.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "granular/analysis/exponent_report.hpp"
#include "granular/analysis/summary_statistics.hpp"
#include "granular/case/spreading_run.hpp"
#include "granular/case/transport_case.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/error.hpp"

namespace granular {

/// γ about the site and about the centroid, and η, of curves sampled at `t`.
struct TransportExponents {
  ExponentReport gamma_site, gamma_centroid;
  ExponentReport eta;  ///< P⁻¹ ∝ t^−η, fitted as 1/P⁻¹ ∝ t^η
  const ExponentReport& gamma(SpreadCentre c) const { return c == SpreadCentre::site ? gamma_site : gamma_centroid; }
};
TransportExponents transport_exponents(const TransportCase& c, const std::vector<double>& t,
                                       const std::vector<double>& m2_site, const std::vector<double>& m2_centroid,
                                       const std::vector<double>& ipr);

struct TransportSummary {
  std::vector<double> t;                        ///< sample times [s]
  SeriesSummary m2, m2_centroid;                ///< m̃2 about the site and about the centroid [bead²]
  SeriesSummary ipr, energy_error;              ///< over realizations, at the sample times
  SeriesSummary profile;                        ///< site energies E_n at T (empty if not asked for)
  SeriesSummary mle;                            ///< X1(t) [1/s] (empty unless dynamics.integration.lyapunov.enabled)
  std::optional<TransportExponents> exponents;  ///< with realization errors; absent when not fitted
  double max_energy_error = 0;                  ///< worst |H(t)−H0|/H0 of any realization
  std::size_t reached_walls = 0;                ///< realizations whose energy reached the walls
  std::size_t realizations = 0;                 ///< realizations averaged (excluded ones not counted)
  std::vector<std::uint64_t> excluded;          ///< realizations that failed and were left out (skip_failed)
};

/// One realization of a case failed (a guard tripped, a NaN): which one, of which case, so that a
/// front end can say how to replay it alone. Every realization finished before it stays in the
/// checkpoint. what() is "realization r of seed s: <cause>".
struct RealizationFailed : NumericalError {
  RealizationFailed(const TransportCase& c, std::uint64_t r, const std::string& cause)
      : NumericalError("realization " + std::to_string(r) + " of seed " + std::to_string(c.chain.seed) + ": " + cause),
        failed_case(c), realization(r) {}
  TransportCase failed_case;
  std::uint64_t realization;
};

/// Threads, checkpoint, resume, progress: the library's one run-options type.
using StudyRunOptions = RunOptions;

/// Runs (or resumes) the ensemble; under mpirun only rank 0 gets a filled summary. A failing
/// realization throws RealizationFailed, unless options.skip_failed: then it is logged as failed
/// (an empty record), left out of every mean and listed in `excluded`; a later resume without
/// skip_failed stops at it again. Bit-identical for any thread count, rank count or interruption. Memory: the R records
/// of the case (4 series on every sample, E_n(T) for the profiled ones) while it runs.
TransportSummary run_transport_study(const TransportCase& c, const StudyRunOptions& options);

/// JSON of an exponent report: fit, mean L_d, verdict, which one is shown, realization errors.
nlohmann::json to_json(const ExponentReport& report);

/// The exponents as a run's JSON carries them: gamma, gamma_err, gamma_real_err (the γ about
/// `shown`), eta, eta_err, eta_real_err, power_law (of that γ), and "exponents" with every report.
nlohmann::json to_json(const TransportExponents& exponents, SpreadCentre shown);

/// Warnings a user must see about a run or an ensemble (energy at the walls, the energy guard).
std::vector<std::string> warnings(const SpreadingResult& run, const SpreadingRunConfig& config);
std::vector<std::string> warnings(const TransportSummary& summary, const SpreadingRunConfig& config);
/// Notes on the case itself, before any run: a fit window beyond T (no exponents fitted).
std::vector<std::string> notes(const TransportCase& c);
/// What a user must be told of the realizations of `c` left out (RunOptions::skip_failed): "N failed
/// realization(s) of R left out"; "" when none was.
std::string excluded_note(const TransportCase& c, const TransportSummary& summary);

}  // namespace granular
