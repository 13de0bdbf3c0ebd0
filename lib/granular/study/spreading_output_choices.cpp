#include "granular/study/spreading_output_choices.hpp"

#include <utility>

#include "granular/error.hpp"

namespace granular {
namespace {

/// `value` as a count of `name` in lo … 1e8.
std::size_t output_count(long long value, const char* name, long long lo) {
  constexpr long long most = 100000000;
  if (value < lo) throw InvalidInput(name, " " + std::to_string(value) + ": must be >= " + std::to_string(lo));
  if (value > most) throw InvalidInput(name, " " + std::to_string(value) + ": must be <= " + std::to_string(most));
  return static_cast<std::size_t>(value);
}

}  // namespace

void apply(const SpreadingOutputChoices& o, TransportCase& c) {
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
