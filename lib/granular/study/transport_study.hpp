#pragma once
// One cell of the paper's transport study (SPEC §4 "Ensembles and exponents"): R realizations of
// a disordered chain kicked at one site, integrated to T, averaged, and fitted. This is where the
// model (which chain), dynamics (how one realization evolves), ensemble (how many, where) and
// analysis (what the averages say) meet; none of them knows about the others.
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "granular/analysis/power_law_fit.hpp"
#include "granular/analysis/summary_statistics.hpp"
#include "granular/dynamics/spreading.hpp"
#include "granular/ensemble/progress_meter.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/material.hpp"

namespace granular {

enum class Kick { displacement, velocity };
Kick parse_kick(const std::string& name);
std::string to_string(Kick kick);

struct TransportCase {
  Disorder disorder = Disorder::anderson;
  double q = 0.5, xi = 0.5;
  std::size_t n = 2501;
  double precompression = 10;          ///< F0 [N]
  double r1 = 4.76e-3;                 ///< type-1 radius [m]
  Kick kick = Kick::displacement;
  double alpha = 1e-7;                 ///< displacement kick [m]
  double beta = 8e-3;                  ///< velocity kick [m/s]
  bool match_beta = false;             ///< velocity kick carrying the energy of α on each chain instead
  std::size_t site = 1250;             ///< 0-based kicked bead (1251 counting from 1)
  SpreadingConfig dynamics;            ///< T, τ, integrator, force law, samples, window
  std::uint64_t seed = 1;
  std::size_t realizations = 500;
  std::size_t profile_realizations = std::numeric_limits<std::size_t>::max();  ///< E_n(T) averaged over the first this many (0: none)
  bool fit = true;                          ///< fit γ and η (needs fit_end ≤ T)
  double fit_begin = 4e-3, fit_end = 1e-2;  ///< exponents fitted on [fit_begin, fit_end] s
  PowerLawCriterion criterion;
};

/// Throws InvalidInput (naming the option) on an impossible case, before any work.
void validate(const TransportCase& c);

/// Every parameter that determines the result, as JSON (the checkpoint's identity).
nlohmann::json describe(const TransportCase& c);

struct TransportSummary {
  std::vector<double> t;               ///< sample times [s]
  SeriesSummary m2, ipr, energy_error; ///< over realizations, at the sample times
  SeriesSummary profile;               ///< site energies E_n at T (empty if not asked for)
  PowerLawAnalysis gamma;              ///< m̃2 ∝ t^γ on the fit window (zero when not fitted)
  PowerLawAnalysis eta;                ///< P⁻¹ ∝ t^−η (fitted as 1/P⁻¹ ∝ t^η)
  double max_energy_error = 0;         ///< worst |H(t)−H0|/H0 of any realization
  std::size_t reached_walls = 0;       ///< realizations whose energy reached the walls
  std::size_t realizations = 0;
};

struct StudyRunOptions {
  int threads = 0;
  std::string checkpoint;   ///< empty: none
  bool resume = false;
  ProgressMeter* progress = nullptr;
  std::function<bool()> cancelled{};  ///< see RunOptions::cancelled
};

/// Runs (or resumes) the ensemble; under mpirun only rank 0 gets a filled summary.
/// Bit-identical for any thread count, rank count or interruption.
TransportSummary run_transport_study(const TransportCase& c, const StudyRunOptions& options);

}  // namespace granular
