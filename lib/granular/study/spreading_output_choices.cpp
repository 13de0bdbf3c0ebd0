#include "granular/study/spreading_output_choices.hpp"

#include <utility>

#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"

namespace granular {
namespace {

/// `value` as a count of `name` in lo … 1e8.
std::size_t output_count(long long value, const char* name, long long lo) {
  constexpr long long most = 100000000;
  if (value < lo) throw InvalidInput(name, " " + std::to_string(value) + ": must be >= " + std::to_string(lo));
  if (value > most) throw InvalidInput(name, " " + std::to_string(value) + ": must be <= " + std::to_string(most));
  return static_cast<std::size_t>(value);
}

// The command line's text form of `forces_at`: a comma list of beads; an empty text is none.
void read_beads(SpreadingOutputChoices& o, const std::string& text) {
  o.forces_at = text.empty() ? std::vector<long>{} : parse_integer_list(text, "forces_at");
}
std::string write_beads(const SpreadingOutputChoices& o) {
  std::string out;
  for (long s : o.forces_at) {
    if (!out.empty()) out += ',';
    out += std::to_string(s);
  }
  return out;
}

}  // namespace

const ParameterTable<SpreadingOutputChoices>& spreading_output_parameters() {
  using O = SpreadingOutputChoices;
  using P = Parameter<O>;
  static const ParameterTable<O> table{
      {"forces_at",
       &O::forces_at,
       {read_beads, write_beads},
       "beads 1..N (e.g. 601,631,661) whose force [N] is recorded at `force_samples` uniform times",
       false},
      P{"force_samples", &O::force_samples, "uniform times 0..T of the force series (>= 2)"}.needing("forces_at"),
      {"energy_map", &O::energy_map, "record the energy map E_n(t): `map_samples` times, `map_stride` beads a column"},
      P{"map_samples", &O::map_samples, "uniform times 0..T of the `energy_map` (>= 2)"}.needing("energy_map"),
      P{"map_stride", &O::map_stride, "beads summed into one column of the `energy_map` (>= 1)"}.needing("energy_map"),
      {"spectral_density", &O::spectral_density,
       "compute the spectral density g(nu) of the series of `spectrum_of`, sampled at `spectrum_samples` times"},
      P{"spectrum_samples", &O::spectrum_samples, "uniform samples 0..T of the series for the `spectral_density` (>= 2)"}
          .needing("spectral_density"),
      P{"spectrum_of", &O::spectrum_of,
        "displacement (the paper's g) | velocity (a permanent step in u adds a flat floor, not a 1/nu^2 tail)"}
          .needing("spectral_density")};
  return table;
}

void apply(const SpreadingOutputChoices& o, TransportCase& c) {
  refuse_unmet_needs(o, spreading_output_parameters());  // `map_stride` without `energy_map` is refused
  const std::size_t beads = c.chain.size();
  SpreadingRunConfig& d = c.dynamics;
  d.forces.sites.clear();
  for (long s : o.forces_at) {
    if (s < 1 || static_cast<std::size_t>(s) > beads)
      throw InvalidInput("forces_at",
                         " " + std::to_string(s) + ": outside the chain of " + std::to_string(beads) + " beads (1..N)");
    d.forces.sites.push_back(static_cast<std::size_t>(s - 1));
  }
  d.forces.samples = output_count(o.force_samples, "force_samples", 2);
  const EnergyMapObserver::Settings map{output_count(o.map_samples, "map_samples", 2),
                                        output_count(o.map_stride, "map_stride", 1)};
  const std::size_t spectrum_samples = output_count(o.spectrum_samples, "spectrum_samples", 2);
  SpectrumSource source{};
  try {
    source = parse_spectrum_source(o.spectrum_of);
  } catch (const InvalidInput& e) {  // the parser names the library's `spectrum_source`
    throw InvalidInput("spectrum_of", e.problem());
  }
  d.energy_map.reset();
  if (o.energy_map) d.energy_map = map;
  d.spectrum.reset();
  if (o.spectral_density) d.spectrum = SpectralDensityObserver::Settings{spectrum_samples, source};
}

}  // namespace granular
