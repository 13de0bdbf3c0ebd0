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
#include "granular/study/breather_branch.hpp"
#include "granular/study/frequency_slips.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Breathers of one precompressed chain: periodic orbits by half-period shooting (Newton, Jacobian from\n"
      "the tangent map), continued in frequency from a linear mode (--mode K, or --near-khz F, or the mode\n"
      "nearest --start-khz outside the bands, or a state from --seed-file at --start-khz), with Floquet\n"
      "multipliers. At --F0 0 only on on-site springs (--quasi s1 --k0-n-per-m K [N/m]): seeded from one\n"
      "bead (--site) above its on-site frequency. Writes PREFIX.csv (columns "
      "omega_rad_s,freq_khz,energy_J,amplitude_m,centre,max_multiplier,\n"
      "stable,complete,verdict_trusted,newton_iterations,residual,max_open_fraction; verdict_trusted 0 at --F0 0,\n"
      "where the Floquet verdict does not converge with the steps per period), PREFIX.h5 (profiles x0,\n"
      "multipliers, open fractions per point) and PREFIX.json (parameters, Newton histories, multiplier checks).",
      "breathers"};
  tool::describe_common(app);
  tool::ChainOptions chain_options;
  tool::add_chain_options(app, chain_options);
  BreatherBranchConfig config;
  std::string law = "hertz", scheme = "saba2c", output = "breathers", continuation = "natural", seed_file,
              newton = "auto", floquet = "auto";
  bool quiet = false, through_opening = false;
  tool::add_integer(app, "--mode", config.mode, "seed: linear mode number 1..N (0: by --near-khz or --start-khz)");
  app.add_option("--near-khz", config.near_khz, "seed: the linear mode nearest this frequency [kHz]");
  app.add_option(
      "--start-khz", config.start_khz,
      "first breather frequency [kHz] (default: the seed's, shifted by --start-offset towards --target-khz)");
  tool::add_option(app, "--start-offset", config.start_offset, "relative shift of the first frequency from the seed");
  tool::add_integer(app, "--site", config.site,
                    "F0 = 0 (on-site springs: --quasi s1 --k0-n-per-m K): seed bead 1..N (0: the middle one)");
  app.add_option("--target-khz", config.target_khz, "stop at this frequency [kHz] (default: no target, go down)");
  app.add_option("--seed-file", seed_file,
                 "seed: a state at rest, one displacement [m] per bead and line ('#' comments), Newton's first guess "
                 "at --start-khz (instead of a mode)");
  tool::add_option(app, "--step-khz", config.step_khz,
                   "first continuation step [kHz] (0: the start's distance from the seed; 0.1 % of it from a file)");
  tool::add_option(app, "--continuation", continuation,
                   "natural (in frequency; a fold ends the branch) | arclength (pseudo-arclength: passes folds)");
  tool::add_integer(app, "--max-points", config.max_points, "points on the branch at most");
  tool::add_option(app, "--law", law, "bond force law: hertz | fpu");
  tool::add_option(app, "--scheme", scheme,
                   "splitting scheme of shooting and monodromy: saba2c | saba2 | aba864 | srkn14a");
  tool::add_integer(app, "--steps-per-period", config.shooting.steps_per_period,
                    "scheme steps per period, even (0: omega_max tau <= 0.05, at least 128)");
  tool::add_option(app, "--tolerance", config.shooting.tolerance,
                   "Newton stops at relative residual |du/dt(T/2)| / (omega_b |x0|) <= this");
  tool::add_option(
      app, "--newton", newton,
      "Newton's linear solve: dense (N x N Jacobian) | krylov (matrix-free GMRES) | auto (dense to N = 1000)");
  tool::add_option(app, "--floquet", floquet,
                   "multipliers: dense (all 2N) | arpack (the --multipliers largest |mu|) | auto (dense to N = 1000, "
                   "then ARPACK; up to N = 3000 within the dense cost, then dense unless all converged)");
  tool::add_integer(app, "--multipliers", config.floquet_multipliers, "ARPACK: how many multipliers of largest |mu|");
  tool::add_option(app, "--stability-tolerance", config.stability_tolerance, "stable when max |multiplier| <= 1 + this");
  app.add_flag("--through-opening", through_opening, "continue past points where a contact opens");
  tool::add_output_option(app, output);
  app.add_flag("--quiet", quiet, "no progress lines on stderr");

  return tool::run(
      app, argc, argv,
      [&] {
        tool::Metadata meta("breathers", argc, argv);
        config.chain = tool::chain_recipe(chain_options);
        config.realization = chain_realization(chain_options);
        config.law = parse_force_law(law);
        if (config.law == ForceLawKind::linear)
          throw InvalidInput("--law",
                             " linear: every amplitude is a periodic orbit at a mode's frequency; use hertz or fpu");
        config.shooting.scheme = parse_scheme(scheme, "--scheme");
        config.stop_at_opening = !through_opening;
        config.continuation = parse_continuation(continuation);
        config.shooting.newton = parse_newton_method(newton);
        config.floquet_method = parse_floquet_method(floquet);
        if (!seed_file.empty()) config.seed_profile = read_displacements_file(seed_file, "seed_profile");
        validate(config);
        load_hdf5_writer();  // the profiles' file: a missing component fails here, not after the branch
        tool::warn(frequency_slips(config, [](const std::string& p) { return tool::option_name(p); }));  // Hz as kHz
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
      {{"seed_profile", "--seed-file"}, {"floquet_multipliers", "--multipliers"}, {"floquet_method", "--floquet"}});
}
