#pragma once
// The options of `spreading`'s outputs beyond PREFIX.csv: the final state, the profile, force
// series, the energy map (HDF5) and the spectral density g(ν), with their sampling (the files
// themselves: study/spreading_files.hpp; the choices, their meaning and the rule that makes
// observers of them, shared with Python: study/spreading_output_choices.hpp).
#include <set>
#include <string>

#include <CLI/CLI.hpp>

#include "granular/study/spreading_output_choices.hpp"
#include "tool_main.hpp"

namespace granular::tool {

/// The library's choices, bound straight to the flags (--forces-at by its text form), with what
/// only the command line has: the files, whose names ask for the energy map and g(ν).
struct SpreadingOutputs : SpreadingOutputChoices {
  std::string final_state, energy_map_file, spectrum_file;
  bool profile = false;
  /// Outputs that describe one realization (--realization), computed even beside an ensemble.
  bool single() const {
    return !final_state.empty() || !forces_at.empty() || !energy_map_file.empty() || !spectrum_file.empty();
  }
};

inline void add_spreading_outputs(CLI::App& app, SpreadingOutputs& o) {
  const auto add = [&](std::set<std::string> only) {
    return add_parameters<SpreadingOutputChoices>(app, o, spreading_output_parameters(),
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

/// Sets what the options ask of c's dynamics (needs c.chain): the files ask for their outputs.
inline void apply(SpreadingOutputs o, TransportCase& c) {
  o.energy_map = !o.energy_map_file.empty();
  o.spectral_density = !o.spectrum_file.empty();
  granular::apply(static_cast<const SpreadingOutputChoices&>(o), c);
}

}  // namespace granular::tool
