#pragma once
// The `klein-gordon` job's case and its schema (parameter_table.hpp): a DKG run (klein_gordon_run.hpp)
// with its final time, log-spaced samples and ensemble, described once. The tool's options and
// --help, Python's keywords and docstring, validation and the JSON (describe_rows / parse_rows) are
// all made from klein_gordon_parameters(). Units are the model's (docs/physics.md, "The disordered
// Klein–Gordon chain"): time in 1/ω₀, energy in those of H.
//
//   granular::KleinGordonCase c;           // N = 1000, W = 4, one site at E = 0.4, T = 1e4
//   c.run.block = 21;                      // a block of 21 sites at energy density h = c.run.energy
//   c.realizations = 8;
#include <cstdint>
#include <vector>

#include "granular/klein_gordon/klein_gordon_run.hpp"
#include "granular/parameter_table.hpp"

namespace granular {

struct KleinGordonCase {
  /// The chain, the excitation, τ and whether Λ is computed; its sample_steps are sample_steps(case).
  KleinGordonRunConfig run{};
  double duration = 1e4;           ///< T [1/ω₀]: the last sample, at step round(T/τ)
  long samples = 50;               ///< sample times, log-spaced from τ to T (repeated steps dropped)
  unsigned long realizations = 1;  ///< realizations 0 … count − 1 of `seed`; more than one: their means
  int threads = 0;                 ///< over realizations; 0: every core. Results do not depend on it
  /// The exponents' window {t0, t1} [1/ω₀] (klein_gordon_exponents.hpp); empty: no exponents.
  std::vector<double> fit{};
};

/// The case's rows, in the order front ends show them: the chain, the excitation, the run, the ensemble.
const ParameterTable<KleinGordonCase>& klein_gordon_parameters();

/// The rule of the samples, as the JSON states it: step round(n^(k/(S−1))) for k = 0 … S − 1,
/// n = round(T/τ), S = `samples`, repeats dropped (one sample: step n).
extern const char* const klein_gordon_sample_rule;

/// The sample steps of `c` by that rule: increasing, from 1 to round(T/τ).
std::vector<std::uint64_t> sample_steps(const KleinGordonCase& c);

/// c.run with its sample_steps set: what run_klein_gordon and klein_gordon_ensemble take.
KleinGordonRunConfig run_config(const KleinGordonCase& c);

/// Throws InvalidInput naming the row of a value out of range (`duration`, `samples`,
/// `realizations`, `threads`, `fit`, `energy_map` (samples × N above its limit), and those validate(KleinGordonRunConfig)
/// names). A `fit` window is refused unless it is {t0, t1} with 0 < t0 < t1 ≤ T holding at least 3 samples.
void validate(const KleinGordonCase& c);

}  // namespace granular
