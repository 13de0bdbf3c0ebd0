// breathers: a branch of time-periodic localized orbits (breathers) of one chain, by half-period
// shooting with Newton's method, continued in frequency from a linear mode, with the Floquet
// multipliers of every point and the fraction of the period each contact is open.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "common/chain_options.hpp"
#include "common/outputs.hpp"
#include "common/tool_main.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/hdf5_file.hpp"
#include "granular/model/configuration_file.hpp"
#include "granular/orbits/breather_branch.hpp"
#include "granular/orbits/breather_parameters.hpp"
#include "granular/study/frequency_slips.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Breathers of one precompressed chain: periodic orbits by half-period shooting (Newton, Jacobian from\n"
      "the tangent map), continued in frequency from a linear mode (--mode K, or --near F, or the mode\n"
      "nearest --start-khz outside the bands, or a state from --seed-file at --start-khz), with Floquet\n"
      "multipliers. At --F0 0 only on on-site springs (--quasi s1 --k0-n-per-m K [N/m]): seeded from one\n"
      "bead (--site) above its on-site frequency. Writes PREFIX.csv (columns "
      "omega_rad_s,freq_khz,energy_J,amplitude_m,centre,max_multiplier,\n"
      "stable,complete,verdict_trusted,newton_iterations,residual,max_open_fraction; verdict_trusted 0 at --F0 0,\n"
      "where the Floquet verdict does not converge with the steps per period), PREFIX.h5 (profiles x0,\n"
      "multipliers, open fractions, verdict_trusted per point) and PREFIX.json (parameters, Newton\n"
      "histories, multiplier checks).",
      "breathers"};
  tool::describe_common(app);
  tool::ChainOptions chain_options;
  tool::add_chain_options(app, chain_options);
  BreatherBranchConfig config;
  std::string output = "breathers", seed_file;
  bool quiet = false;
  tool::add_parameters(app, config, breather_parameters());
  app.add_option("--seed-file", seed_file,
                 "seed: a state at rest, one displacement [m] per bead and line ('#' comments), Newton's first guess "
                 "at --start-khz (instead of a mode)");
  tool::add_output_option(app, output);
  app.add_flag("--quiet", quiet, "no progress lines on stderr");

  return tool::run(
      app, argc, argv,
      [&] {
        tool::Metadata meta("breathers", argc, argv);
        config.chain = tool::chain_recipe(chain_options);
        config.realization = chain_realization(chain_options);
        if (!seed_file.empty()) config.seed_profile = read_displacements_file(seed_file, "seed_profile");
        validate(config);
        load_hdf5_writer();  // the profiles' file: a missing component fails here, not after the branch
        tool::warn(frequency_slips(config, [](const std::string& p) { return tool::option_name(front_end_word(p)); }));
        tool::warn(radius_warnings(config.chain, tool::radius_options(chain_options)));
        const auto claim = tool::claim_output(output, meta.command());
        const TableOutputs paths = table_outputs(output);
        const std::string h5 = output + ".h5";
        check_writable(h5);
        const auto branch = continue_breather(config, [&](const BreatherPoint& p) {
          if (!quiet)
            std::fprintf(stderr, "breathers: %.6f kHz  E = %.4g J  max|mu| = %.10f  Newton %d  residual %.2g\n",
                         p.freq_khz, p.energy, p.floquet.max_modulus, p.iterations, p.residual);
        });
        if (!quiet)
          std::fprintf(stderr, "breathers: %zu points; stopped: %s\n", branch.points.size(), branch.stop_reason.c_str());
        if (!quiet && !branch.verdict_untrusted_reason.empty())
          std::fprintf(stderr, "breathers: Floquet verdicts untrusted: %s\n", branch.verdict_untrusted_reason.c_str());
        AtomicFile csv(paths.csv);
        write_breather_csv(csv.stream(), branch);
        meta.merge(describe_breather_branch(config, branch));
        const auto profiles = write_breather_hdf5(h5, branch);
        meta["output"] = paths.csv;
        meta["profiles"] = h5;
        meta.write(paths.json, {&csv, profiles.get()});
      },
      {{"seed_profile", "--seed-file"}});
}
