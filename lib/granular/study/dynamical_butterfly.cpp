#include "granular/study/dynamical_butterfly.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

#include "granular/case/time_step_rule.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/sampling.hpp"
#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/error.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/model/random_stream.hpp"
#include "granular/number_format.hpp"
#include "granular/study/butterfly.hpp"

namespace granular {
namespace {

Chain chain_at(const DynamicalButterflyConfig& c, double beta) { return at_ratio(c.chain, beta).chain(c.realization); }

IntegrationConfig integration_of(const DynamicalButterflyConfig& c) {
  IntegrationConfig i = c.integration;
  i.window.enabled = false;  // every bead moves from t = 0: a window would only cost its bookkeeping
  return i;
}

std::uint64_t total_steps(const DynamicalButterflyConfig& c) {
  return static_cast<std::uint64_t>(std::llround(c.integration.duration / c.integration.time_step));
}

// The sample interval Δt of the spectrum: what sample_steps() gives the observer.
double sample_interval(const DynamicalButterflyConfig& c) {
  const std::vector<std::uint64_t> steps = sample_steps(total_steps(c), c.spectrum_samples, Sampling::uniform);
  return static_cast<double>(steps.size() > 1 ? steps[1] : 1) * c.integration.time_step;
}

// The fewest samples K ≥ at_least whose K − 1 intervals divide the run's steps (so that they span
// [0, T] and the resolution is 1/T); all steps (one sample per step) when none is fewer.
std::uint64_t spanning_samples(std::uint64_t steps, std::uint64_t at_least) {
  for (std::uint64_t k = std::max<std::uint64_t>(at_least, 2); k <= steps; ++k)
    if (steps % (k - 1) == 0) return k;
  return steps + 1;
}

// The least energy that stretches a bond of `chain` from its static overlap to zero (Hertz, the
// real contact, whatever law the run integrates): below it no contact can open.
double opening_energy(const Chain& chain) {
  const ForceLaw hertz = make_force_law(ForceLawKind::hertz, chain);
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < chain.bonds(); ++k)
    least = std::min(least, std::visit([&](const auto& l) { return l.potential(k, -chain.overlap[k]); }, hertz));
  return least;
}

}  // namespace

namespace {
using O = DynamicalButterflyConfig;
void read_integrator(O& c, const std::string& word) { c.integration.integrator = parse_integrator(word); }
std::string write_integrator(const O& c) { return c.integration.integrator.name(); }
void read_force_law(O& c, const std::string& word) { c.integration.force_law = parse_force_law(word); }
std::string write_force_law(const O& c) { return to_string(c.integration.force_law); }
void read_source(O& c, const std::string& word) {
  try {
    c.source = parse_spectrum_source(word);
  } catch (const InvalidInput&) {  // the library names its own field; the row is `spectrum_of`
    throw InvalidInput("spectrum_of", " '" + word + "': displacement or velocity");
  }
}
std::string write_source(const O& c) { return to_string(c.source); }
}  // namespace

const ParameterTable<DynamicalButterflyConfig>& dynamical_butterfly_parameters() {
  using P = Parameter<O>;
  static const ParameterTable<O> table{
      {"duration", path<O>(&O::integration, &IntegrationConfig::duration),
       "duration [s]; the frequency resolution is 1/T"},
      {"time_step", path<O>(&O::integration, &IntegrationConfig::time_step), "time step tau [s]"},
      P{"integrator", {}, {read_integrator, write_integrator}, "saba2c | saba2 | aba864 | srkn14a | reference"}.as_word(),
      P{"force_law", {}, {read_force_law, write_force_law}, "hertz | fpu | linear"}.as_word(),
      {"amplitude", &O::amplitude, "initial velocities uniform in [-a, a] [m/s], small enough to stay linear"},
      {"velocity_seed", &O::velocity_seed, "seed of the initial velocities"},
      {"spectrum_samples", &O::spectrum_samples, "uniform samples of [0, T] transformed (Nyquist about samples/(2T))"},
      {"max_energy_error", &O::max_energy_error, "relative energy error that stops a run, 0 = off"},
      P{"spectrum_of", {}, {read_source, write_source}, "velocity | displacement: whose power is summed over beads"}
          .as_word()};
  return table;
}

State random_velocities(std::size_t beads, double amplitude, std::uint64_t velocity_seed) {
  State s(beads);
  RandomStream stream(velocity_seed, 0);
  for (double& v : s.v) v = amplitude * (2 * stream.uniform() - 1);
  return s;
}

void validate(const DynamicalButterflyConfig& c) {
  validate_ratios(c.chain, c.ratios);
  if (!(c.chain.F0 > 0))
    throw InvalidInput("F0", " " + format_number(c.chain.F0) + ": the linear spectrum needs F0 > 0");
  if (!std::isfinite(c.amplitude) || !(c.amplitude > 0))
    throw InvalidInput("amplitude", " " + format_number(c.amplitude) + " m/s: must be finite and > 0");
  validate(integration_of(c));
  if (c.spectrum_samples < 2) throw InvalidInput("spectrum_samples", ": at least 2");
  const std::uint64_t steps = total_steps(c);
  if (c.max_energy_error < 0 || !std::isfinite(c.max_energy_error))
    throw InvalidInput("max_energy_error", " " + format_number(c.max_energy_error) + ": must be >= 0");
  const double nyquist_hz = 1 / (2 * sample_interval(c));
  const State initial = random_velocities(c.chain.N, c.amplitude, c.velocity_seed);
  for (double beta : c.ratios) {
    const Chain chain = chain_at(c, beta);
    const ForceLaw law = make_force_law(c.integration.force_law, chain);
    const double energy = total_energy(law, chain, initial);
    const double opening = opening_energy(chain);
    if (!(energy < opening))
      throw InvalidInput("amplitude", " " + format_number(c.amplitude) + " m/s: its energy " + format_number(energy) +
                                          " J could open a contact of the chain at ratio " + format_number(beta) +
                                          " (from " + format_number(opening) +
                                          " J): far from linear; take an amplitude well below");
    const double omega_max = highest_frequency_bound(law, chain, energy);
    if (!c.integration.integrator.reference) {
      const double limit = stable_step_limit(c.integration.integrator.scheme) / omega_max;
      if (c.integration.time_step > limit)
        throw InvalidInput("time_step", " " + format_number(c.integration.time_step) +
                                            " s: past the stability limit of " + c.integration.integrator.name() +
                                            " on the chain at ratio " + format_number(beta) +
                                            "; the largest stable time step is " + format_number(limit) + " s");
    }
    const double top_hz = omega_max / (2 * std::numbers::pi);
    if (top_hz >= nyquist_hz) {
      const auto needed = static_cast<std::uint64_t>(std::ceil(2 * top_hz * c.integration.duration * 1.05)) + 1;
      throw InvalidInput("spectrum_samples", " " + std::to_string(c.spectrum_samples) + ": the Nyquist frequency " +
                                                 format_number(nyquist_hz / 1e3) +
                                                 " kHz is below the highest frequency bound " +
                                                 format_number(top_hz / 1e3) + " kHz of the chain at ratio " +
                                                 format_number(beta) + " (its peaks would alias); take " +
                                                 std::to_string(spanning_samples(steps, needed)) + " samples");
    }
  }
  // Samples that stop short of T would make the resolution coarser than 1/T, and silently so.
  if (steps % (c.spectrum_samples - 1) != 0)
    throw InvalidInput("spectrum_samples", " " + std::to_string(c.spectrum_samples) +
                                               ": the samples must span [0, T], i.e. samples - 1 must divide the " +
                                               std::to_string(steps) +
                                               " steps of the run (T over the time step); e.g. " +
                                               std::to_string(spanning_samples(steps, c.spectrum_samples)));
  SpectralDensityObserver::Settings{c.spectrum_samples, c.source}.validate(
      {c.chain.N, steps, c.integration.time_step, c.integration.duration});
}

std::vector<DynamicalButterflyColumn> compute_dynamical_butterfly(const DynamicalButterflyConfig& c,
                                                                  const RunOptions& run) {
  validate(c);
  const State initial = random_velocities(c.chain.N, c.amplitude, c.velocity_seed);
  const IntegrationConfig integration = integration_of(c);
  std::vector<DynamicalButterflyColumn> columns(c.ratios.size());
  parallel_realizations(
      c.ratios.size(), resolve_threads(run.threads),
      [&](std::size_t i, int) {
        if (run.cancelled && run.cancelled()) throw Cancelled();
        const Chain chain = chain_at(c, c.ratios[i]);
        // The energy observer only guards the run (its error is reported); the spectrum is the measurement.
        EnergySpreadObserver energy(
            {.samples = 50, .sampling = Sampling::uniform, .max_energy_error = c.max_energy_error, .wall_warning = 2});
        SpectralDensityObserver density({c.spectrum_samples, c.source});
        const RunInfo info = spread(chain, initial, integration, energy, density);
        DynamicalButterflyColumn& col = columns[i];
        col.ratio = c.ratios[i];
        col.freq_khz = std::move(density.freq_khz);
        col.power = std::move(density.density);
        col.initial_energy = info.initial_energy;
        col.opening_energy = opening_energy(chain);
        col.max_energy_error = energy.max_energy_error;
      },
      run.progress);
  return columns;
}

void write_dynamical_butterfly_csv(std::ostream& out, const std::vector<DynamicalButterflyColumn>& columns) {
  CsvWriter table(out, {"ratio", "freq_khz", "power"});
  for (const DynamicalButterflyColumn& col : columns)
    for (std::size_t j = 0; j < col.freq_khz.size(); ++j) table.row(col.ratio, col.freq_khz[j], col.power[j]);
}

nlohmann::json describe_dynamical_butterfly(const DynamicalButterflyConfig& c,
                                            const std::vector<DynamicalButterflyColumn>& columns) {
  nlohmann::json meta;
  meta["chain"] = describe(c.chain, c.realization);
  meta["chain"]["quasiperiodic"]["ratio"] = "each of ratios";
  meta["ratios"] = c.ratios;
  meta["realization"] = c.realization;
  meta["from"] = "dynamics";
  meta["initial_state"] = {{"kind", "u = 0, v_n uniform in [-amplitude, amplitude], the same for every ratio"},
                           {"amplitude_m_per_s", c.amplitude},
                           {"velocity_seed", c.velocity_seed}};
  meta["integration"] = {{"duration_s", c.integration.duration},
                         {"time_step_s", c.integration.time_step},
                         {"force_law", to_string(c.integration.force_law)},
                         {"integrator", c.integration.integrator.name()},
                         {"max_energy_error_guard", c.max_energy_error}};
  const double dt = sample_interval(c);
  const std::size_t samples = sample_steps(total_steps(c), c.spectrum_samples, Sampling::uniform).size();
  meta["spectrum"] = {{"of", to_string(c.source)},
                      {"power", "sum over beads of |DFT|^2 of the sampled series, normalized to max 1 per ratio"},
                      {"samples", samples},
                      {"sample_interval_s", dt},
                      {"resolution_khz", 1 / (static_cast<double>(samples) * dt) / 1e3},
                      {"nyquist_khz", 1 / (2 * dt) / 1e3}};
  nlohmann::json energy = nlohmann::json::array(), ratio = nlohmann::json::array(), error = nlohmann::json::array();
  for (const DynamicalButterflyColumn& col : columns) {
    energy.push_back(col.initial_energy);
    ratio.push_back(col.initial_energy / col.opening_energy);
    error.push_back(col.max_energy_error);
  }
  meta["initial_energy_J"] = energy;
  meta["energy_over_opening"] = ratio;
  meta["max_energy_error"] = error;
  return meta;
}

}  // namespace granular
