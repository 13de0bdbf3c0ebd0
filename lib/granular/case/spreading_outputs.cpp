#include "granular/case/spreading_outputs.hpp"

#include <string>
#include <vector>

#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"

namespace granular {
namespace {

using C = TransportCase;
using D = SpreadingRunConfig;
using MapOutput = OptionalSettings<EnergyMapObserver::Settings>;
using SpectrumOutput = OptionalSettings<SpectralDensityObserver::Settings>;

/// Refuses `value` of `name` outside lo … 1e8.
void check_count(std::size_t value, const char* name, std::size_t lo) {
  constexpr std::size_t most = 100000000;
  if (value < lo) throw InvalidInput(name, " " + std::to_string(value) + ": must be >= " + std::to_string(lo));
  if (value > most) throw InvalidInput(name, " " + std::to_string(value) + ": must be <= " + std::to_string(most));
}

// The text form of `forces_at`: a comma list of beads counting from 1 (the observer's are 0-based);
// an empty text is none. Bead 0 or below is in no chain.
void read_beads(C& c, const std::string& text) {
  std::vector<std::size_t>& sites = c.dynamics.forces.sites;
  const std::vector<long> beads = text.empty() ? std::vector<long>{} : parse_integer_list(text, "forces_at");
  for (long s : beads)
    if (s < 1) throw InvalidInput("forces_at", " " + std::to_string(s) + ": outside the chain (beads count from 1)");
  sites.assign(beads.begin(), beads.end());
  for (std::size_t& s : sites) --s;
}
std::string write_beads(const C& c) {
  std::string out;
  for (std::size_t s : c.dynamics.forces.sites) {
    if (!out.empty()) out += ',';
    out += std::to_string(s + 1);
  }
  return out;
}
void read_source(C& c, const std::string& word) {
  try {
    c.dynamics.spectrum->source = parse_spectrum_source(word);
  } catch (const InvalidInput& e) {  // the parser names the library's `spectrum_source`
    throw InvalidInput("spectrum_of", e.problem());
  }
}
std::string write_source(const C& c) { return to_string(c.dynamics.spectrum->source); }

}  // namespace

const ParameterTable<TransportCase>& spreading_output_parameters() {
  using P = Parameter<C>;
  static const auto map = [](auto member) {
    return path<C>(&C::dynamics, &D::energy_map, &MapOutput::settings, member);
  };
  static const auto spectrum_samples =
      path<C>(&C::dynamics, &D::spectrum, &SpectrumOutput::settings, &SpectralDensityObserver::Settings::samples);
  static const ParameterTable<C> table{
      P{"forces_at",
        {},
        {read_beads, write_beads},
        "beads 1..N (e.g. 601,631,661) whose force [N] is recorded at `force_samples` uniform times",
        false}
          .as_word(),
      P{"force_samples", path<C>(&C::dynamics, &D::forces, &ForceObserver::Settings::samples),
        "uniform times 0..T of the force series (>= 2)"}
          .needing("forces_at"),
      {"energy_map", path<C>(&C::dynamics, &D::energy_map, &MapOutput::on),
       "record the energy map E_n(t): `map_samples` times, `map_stride` beads a column"},
      P{"map_samples", map(&EnergyMapObserver::Settings::samples), "uniform times 0..T of the `energy_map` (>= 2)"}
          .needing("energy_map"),
      P{"map_stride", map(&EnergyMapObserver::Settings::stride),
        "beads summed into one column of the `energy_map` (>= 1)"}
          .needing("energy_map"),
      {"spectral_density", path<C>(&C::dynamics, &D::spectrum, &SpectrumOutput::on),
       "compute the spectral density g(nu) of the series of `spectrum_of`, sampled at `spectrum_samples` times"},
      P{"spectrum_samples", spectrum_samples, "uniform samples 0..T of the series for the `spectral_density` (>= 2)"}
          .needing("spectral_density"),
      P{"spectrum_of",
        {},
        {read_source, write_source},
        "displacement (the paper's g) | velocity (a permanent step in u adds a flat floor, not a 1/nu^2 tail)"}
          .as_word()
          .needing("spectral_density")};
  return table;
}

void validate_outputs(const TransportCase& c) {
  refuse_unmet_needs(c, spreading_output_parameters());  // `map_stride` without `energy_map` is refused
  const std::size_t beads = c.chain.size();
  const SpreadingRunConfig& d = c.dynamics;
  for (std::size_t s : d.forces.sites)
    if (s >= beads)
      throw InvalidInput("forces_at", " " + std::to_string(s + 1) + ": outside the chain of " + std::to_string(beads) +
                                          " beads (1..N)");
  check_count(d.forces.samples, "force_samples", 2);
  check_count(d.energy_map->samples, "map_samples", 2);
  check_count(d.energy_map->stride, "map_stride", 1);
  check_count(d.spectrum->samples, "spectrum_samples", 2);
}

}  // namespace granular
