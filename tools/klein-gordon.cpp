// klein-gordon: energy spreading and weak chaos in the disordered Klein–Gordon chain (docs/chaos.md,
// "The DKG chain from the shell and Python"): one site of energy E or a block of L sites at energy
// density h, SABA2C, and at log-spaced times the second moment m2, the participation number P and
// the finite-time maximal Lyapunov exponent Λ, of one realization or the means of an ensemble.
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/outputs.hpp"
#include "common/tool_main.hpp"
#include "granular/files/klein_gordon_files.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/output_paths.hpp"
#include "granular/klein_gordon/klein_gordon_study.hpp"
#include "granular/parameter_json.hpp"

namespace {

/// The case a run's PREFIX.json describes (its "parameters"), `threads` kept from the command line.
granular::KleinGordonCase case_from_file(const std::string& path, int threads) {
  std::ifstream in(path);
  if (!in) throw granular::InvalidInput("--case", " " + path + ": cannot be read");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("parameters") || !j.at("parameters").is_object())
    throw granular::InvalidInput("--case", " " + path + ": not the JSON of a klein-gordon run (no \"parameters\")");
  granular::KleinGordonCase c = granular::parse_rows(j.at("parameters"), granular::klein_gordon_parameters());
  c.threads = threads;
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Spreading and weak chaos in the disordered Klein-Gordon chain (docs/physics.md),\n"
      "  H = sum p^2/2 + e_l x^2/2 + x^4/4 + (x_{l+1} - x_l)^2/(2W), e_l uniform in [1/2, 3/2],\n"
      "in its dimensionless units (time 1/omega0, energy in units of H): one central site of energy E\n"
      "(--block 0) or L central sites at energy density h, integrated by SABA2C up to --T.\n"
      "Writes PREFIX.csv (t,m2,P and, unless --mle=false, mle,mean_log10_mle: one realization's curves or the\n"
      "means of --realizations) and PREFIX.json (every parameter, the sample rule, the energy error and, with\n"
      "--fit t0:t1, the exponents of m2, P and Lambda over that window); with --energy-map, PREFIX-energy.h5\n"
      "(realization 0's site energies E_l at every sample, the spreading tool's layout: energy, t, site).",
      "klein-gordon"};
  tool::describe_common(app);
  KleinGordonCase c;
  std::string output = "klein-gordon", case_file;
  bool quiet = false;
  const auto options = tool::add_parameters(app, c, klein_gordon_parameters());
  tool::add_output_option(app, output);
  auto* file = app.add_option("--case", case_file,
                              "a klein-gordon run's PREFIX.json: its parameters instead of the flags (--threads "
                              "still chooses the threads)");
  for (const auto& [name, option] : options)
    if (name != "threads") option->excludes(file);
  app.add_flag("--quiet", quiet, "no summary on stderr");

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("klein-gordon", argc, argv);
    if (!case_file.empty()) c = case_from_file(case_file, c.threads);
    validate(c);
    const TableOutputs paths{output + ".csv", output + ".json"};
    const auto claim = tool::claim_output(output, meta.command());
    check_writable(paths.csv);
    check_writable(paths.json);
    const std::string map_path = output + "-energy.h5";
    if (c.run.energy_map) {
      check_writable(map_path);
      load_hdf5_writer();  // before the run, not after it
    }
    const KleinGordonResult r = klein_gordon_study(c);
    if (!quiet) {
      const KleinGordonEnsemble& e = r.ensemble;
      std::fprintf(stderr, "klein-gordon: %zu realization(s), t = %.4g: m2 = %.4g, P = %.4g", e.runs.size(),
                   e.time.back(), e.m2.back(), e.participation.back());
      if (!e.mle.empty()) std::fprintf(stderr, ", Lambda = %.4g", e.mle.back());
      std::fprintf(stderr, "; max energy error %.2e\n", r.max_energy_error);
      if (const auto& x = r.exponents)
        std::fprintf(stderr, "klein-gordon: on [%g, %g]: alpha = %.4g, alpha_P = %.4g, alpha_Lambda = %.4g\n", x->begin,
                     x->end, x->alpha.curve, x->alpha_P.curve, x->alpha_Lambda.curve);
    }
    AtomicFile csv(paths.csv);
    write_klein_gordon_csv(csv.stream(), r);
    meta.merge(describe(c, r));
    meta["output"] = paths.csv;
    std::vector<PendingOutput*> files{&csv};
    std::unique_ptr<Hdf5File> map;
    if (c.run.energy_map) {
      map = write_klein_gordon_energy_map(map_path, r);
      files.push_back(map.get());
      meta["energy_map_file"] = map_path;
    }
    meta.write(paths.json, files);
  });
}
