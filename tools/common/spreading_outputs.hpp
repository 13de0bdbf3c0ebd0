#pragma once
// The options of `spreading`'s outputs beyond PREFIX.csv: the final state, the profile, force
// series, the energy map (HDF5) and the spectral density g(ν), with their sampling (the files
// themselves: study/spreading_files.hpp).
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/study/transport_study.hpp"
#include "tool_main.hpp"

namespace granular::tool {

struct SpreadingOutputs {
  std::string final_state, forces_at, energy_map, spectrum, spectrum_of = "displacement";
  long long force_samples = 1000, map_samples = 500, map_stride = 1, spectrum_samples = 2000;
  bool profile = false;
  /// Outputs that describe one realization (--realization), computed even beside an ensemble.
  bool single() const { return !final_state.empty() || !forces_at.empty() || !energy_map.empty() || !spectrum.empty(); }
};

inline void add_spreading_outputs(CLI::App& app, SpreadingOutputs& o) {
  app.add_option("--final-state", o.final_state, "CSV of site,u,v,energy at T");
  app.add_flag("--profile", o.profile,
               "also write PREFIX-profile.csv: site,energy,force at T (ensemble: site,energy,energy_se)");
  app.add_option("--forces-at", o.forces_at,
                 "beads (e.g. 601,631,661) whose force goes to PREFIX-forces.csv: t,site,force");
  add_option(app, "--force-samples", o.force_samples, "uniform times of the force series");
  app.add_option("--energy-map", o.energy_map, "HDF5 file of E_n(t_k): datasets energy [time][column], t, site");
  add_option(app, "--map-samples", o.map_samples, "uniform times of the energy map");
  add_option(app, "--map-stride", o.map_stride, "beads summed into one map column");
  app.add_option("--spectrum", o.spectrum, "CSV of the spectral density: freq_khz,g");
  add_option(app, "--spectrum-samples", o.spectrum_samples, "uniform samples of the series for the spectral density");
  add_option(app, "--spectrum-of", o.spectrum_of,
             "displacement (the paper's g) | velocity (a permanent step in u adds a flat floor, not a 1/nu^2 tail)");
}

/// Checks the options and sets what they ask of c's dynamics (needs c.chain).
inline void apply(const SpreadingOutputs& o, TransportCase& c) {
  for (auto [name, value] : {std::pair{"--force-samples", o.force_samples},
                             {"--map-samples", o.map_samples},
                             {"--map-stride", o.map_stride},
                             {"--spectrum-samples", o.spectrum_samples}})
    if (value < 1) throw InvalidInput(std::string(name) + " " + std::to_string(value) + ": must be >= 1");
  SpreadingRunConfig& d = c.dynamics;
  for (long s : o.forces_at.empty() ? std::vector<long>{} : parse_integer_list(o.forces_at, "--forces-at")) {
    if (s < 1 || static_cast<std::size_t>(s) > c.chain.size())
      throw InvalidInput("--forces-at " + std::to_string(s) + ": outside the chain of " +
                         std::to_string(c.chain.size()) + " beads");
    d.forces.sites.push_back(static_cast<std::size_t>(s - 1));
  }
  d.forces.samples = static_cast<std::size_t>(o.force_samples);
  const SpectrumSource source = parse_spectrum_source(o.spectrum_of);
  if (!o.energy_map.empty())
    d.energy_map =
        EnergyMapObserver::Settings{static_cast<std::size_t>(o.map_samples), static_cast<std::size_t>(o.map_stride)};
  if (!o.spectrum.empty())
    d.spectrum = SpectralDensityObserver::Settings{static_cast<std::size_t>(o.spectrum_samples), source};
}

}  // namespace granular::tool
