#pragma once
// The options of `spreading`'s outputs beyond PREFIX.csv: the final state, the profile, force
// series, the energy map (HDF5) and the spectral density g(ν), with their sampling (the files
// themselves: files/spreading_files.hpp; the sampling's rows over the case, shared with Python:
// case/spreading_outputs.hpp).
#include <set>
#include <string>

#include <CLI/CLI.hpp>

#include "granular/case/spreading_outputs.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// What only the command line has: the files, whose names ask for the energy map and g(ν).
struct SpreadingOutputs {
  std::string final_state, energy_map_file, spectrum_file;
  bool profile = false;
};

/// The output rows bound straight to `run` (--forces-at by its text form), and the files.
inline void add_spreading_outputs(CLI::App& app, SpreadingOutputs& o, TransportCase& run) {
  const auto add = [&](std::set<std::string> only) {
    return add_parameters<TransportCase>(app, run, spreading_output_parameters(),
                                         {.only = only, .flags = {{"spectral_density", "--spectrum"}}});
  };
  app.add_option("--final-state", o.final_state, "CSV of site,u,v,energy at T");
  app.add_flag("--profile", o.profile,
               "also write PREFIX-profile.csv: site,energy,force at T (ensemble: site,energy,energy_se)");
  CLI::Option* forces_at = add({"forces_at", "force_samples"})["forces_at"];
  forces_at->description(forces_at->get_description() + ": PREFIX-forces.csv t,site,force");
  app.add_option("--energy-map", o.energy_map_file, "HDF5 file of E_n(t_k): datasets energy [time][column], t, site");
  add({"map_samples", "map_stride"});
  app.add_option("--spectrum", o.spectrum_file, "CSV of the spectral density: freq_khz,g");
  add({"spectrum_samples", "spectrum_of"});
}

/// The outputs the flags bound to `flags` ask of c's run (the same case, or one a --case file gave,
/// which holds no outputs), the files switching theirs on.
inline void ask_outputs(const SpreadingOutputs& o, const TransportCase& flags, TransportCase& c) {
  c.dynamics.forces = flags.dynamics.forces;
  c.dynamics.energy_map = flags.dynamics.energy_map;
  c.dynamics.spectrum = flags.dynamics.spectrum;
  c.dynamics.energy_map.on = !o.energy_map_file.empty();
  c.dynamics.spectrum.on = !o.spectrum_file.empty();
}

/// Whether `c` asks for outputs that describe one realization (--realization), computed even
/// beside an ensemble.
inline bool single_outputs(const SpreadingOutputs& o, const TransportCase& c) {
  return !o.final_state.empty() || !c.dynamics.forces.sites.empty() || !o.energy_map_file.empty() ||
         !o.spectrum_file.empty();
}

}  // namespace granular::tool
