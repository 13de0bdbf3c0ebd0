#pragma once
// The options of `spreading`'s outputs beyond PREFIX.csv: the final state, the profile, force
// series, the energy map (HDF5) and the spectral density g(ν), with their sampling (the files
// themselves: study/spreading_files.hpp; the rule that makes observers of them, shared with
// Python: study/spreading_output_choices.hpp).
#include <string>

#include <CLI/CLI.hpp>

#include "granular/io/range_syntax.hpp"
#include "granular/study/spreading_output_choices.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// The library's choices, bound straight to the flags, with what only the command line has: the
/// files, and the beads of --forces-at as text.
struct SpreadingOutputs : SpreadingOutputChoices {
  std::string final_state, forces_text, energy_map_file, spectrum_file;
  bool profile = false;
  /// Outputs that describe one realization (--realization), computed even beside an ensemble.
  bool single() const {
    return !final_state.empty() || !forces_text.empty() || !energy_map_file.empty() || !spectrum_file.empty();
  }
};

inline void add_spreading_outputs(CLI::App& app, SpreadingOutputs& o) {
  app.add_option("--final-state", o.final_state, "CSV of site,u,v,energy at T");
  app.add_flag("--profile", o.profile,
               "also write PREFIX-profile.csv: site,energy,force at T (ensemble: site,energy,energy_se)");
  app.add_option("--forces-at", o.forces_text,
                 "beads (e.g. 601,631,661) whose force goes to PREFIX-forces.csv: t,site,force");
  add_option(app, "--force-samples", o.force_samples, "uniform times of the force series");
  app.add_option("--energy-map", o.energy_map_file, "HDF5 file of E_n(t_k): datasets energy [time][column], t, site");
  add_option(app, "--map-samples", o.map_samples, "uniform times of the energy map");
  add_option(app, "--map-stride", o.map_stride, "beads summed into one map column");
  app.add_option("--spectrum", o.spectrum_file, "CSV of the spectral density: freq_khz,g");
  add_option(app, "--spectrum-samples", o.spectrum_samples, "uniform samples of the series for the spectral density");
  add_option(app, "--spectrum-of", o.spectrum_of,
             "displacement (the paper's g) | velocity (a permanent step in u adds a flat floor, not a 1/nu^2 tail)");
}

/// Checks the options and sets what they ask of c's dynamics (needs c.chain).
inline void apply(SpreadingOutputs o, TransportCase& c) {
  if (!o.forces_text.empty()) o.forces_at = parse_integer_list(o.forces_text, "forces_at");
  o.energy_map = !o.energy_map_file.empty();
  o.spectral_density = !o.spectrum_file.empty();
  granular::apply(static_cast<const SpreadingOutputChoices&>(o), c);
}

}  // namespace granular::tool
