#pragma once
// The optional outputs of one spreading run (the observers beyond m̃2 and P⁻¹): the final state,
// the profile, forces at chosen beads, the energy map and the spectral density, with their
// sampling options. Beads count from 1 here, from 0 in the library.
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "granular/dynamics/spreading.hpp"
#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"

namespace granular::tool {

struct RunOutputOptions {
  std::string final_state, forces_at, energy_map, spectrum, spectrum_of = "displacement";
  long long force_samples = 1000, map_samples = 500, map_stride = 1, spectrum_samples = 2000;
  bool profile = false;
};

inline void add_run_output_options(CLI::App& app, RunOutputOptions& o) {
  app.add_option("--final-state", o.final_state, "CSV of site,u,v,energy at T");
  app.add_flag("--profile", o.profile,
               "also write PREFIX-profile.csv: site,energy,force at T (ensemble: site,energy,energy_se)");
  app.add_option("--forces-at", o.forces_at,
                 "beads (e.g. 601,631,661) whose force goes to PREFIX-forces.csv: t,site,force");
  app.add_option("--force-samples", o.force_samples, "uniform times of the force series")->capture_default_str();
  app.add_option("--energy-map", o.energy_map, "HDF5 file of E_n(t_k): datasets energy [time][column], t, site");
  app.add_option("--map-samples", o.map_samples, "uniform times of the energy map")->capture_default_str();
  app.add_option("--map-stride", o.map_stride, "beads summed into one map column")->capture_default_str();
  app.add_option("--spectrum", o.spectrum, "CSV of the spectral density: freq_khz,g");
  app.add_option("--spectrum-samples", o.spectrum_samples, "uniform samples of the series for the spectral density")
      ->capture_default_str();
  app.add_option("--spectrum-of", o.spectrum_of,
                 "displacement (the paper's g) | velocity (a permanent step in u adds a flat floor, not a 1/nu^2 tail)")
      ->capture_default_str();
}

/// Throws InvalidInput naming the flag unless every sample count and the stride are >= 1.
inline void check_counts(const RunOutputOptions& o) {
  for (auto [name, value] : {std::pair{"--force-samples", o.force_samples},
                             {"--map-samples", o.map_samples},
                             {"--map-stride", o.map_stride},
                             {"--spectrum-samples", o.spectrum_samples}})
    if (value < 1) throw InvalidInput(std::string(name) + " " + std::to_string(value) + ": must be >= 1");
}

/// The observers of `d` the options ask for, on a chain of `beads`.
inline void apply(const RunOutputOptions& o, std::size_t beads, SpreadingConfig& d) {
  for (long s : o.forces_at.empty() ? std::vector<long>{} : parse_integer_list(o.forces_at, "--forces-at")) {
    if (s < 1 || static_cast<std::size_t>(s) > beads)
      throw InvalidInput("--forces-at " + std::to_string(s) + ": outside the chain of " + std::to_string(beads) +
                         " beads");
    d.force_sites.push_back(static_cast<std::size_t>(s - 1));
  }
  d.force_samples = static_cast<std::size_t>(o.force_samples);
  d.map_samples = o.energy_map.empty() ? 0 : static_cast<std::size_t>(o.map_samples);
  d.map_stride = static_cast<std::size_t>(o.map_stride);
  d.spectrum_samples = o.spectrum.empty() ? 0 : static_cast<std::size_t>(o.spectrum_samples);
  d.spectrum_source = parse_spectrum_source(o.spectrum_of);
}

}  // namespace granular::tool
