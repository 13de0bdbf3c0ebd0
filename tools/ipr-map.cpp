// ipr-map: mean frequency and inverse participation ratio of every mode of disordered
// chains, over a grid of size ratios ξ and probabilities q (the paper's IPR-map figure).
#include <limits>
#include <string>

#include "common/chain_options.hpp"
#include "common/metadata.hpp"
#include "common/output_claim.hpp"
#include "common/spectrum_options.hpp"
#include "common/tool_main.hpp"
#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/study/ipr_map.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Mean mode frequency [kHz] and displacement IPR of disordered bidisperse chains on a (q, xi) grid.\n"
      "Writes OUTPUT (columns disorder,q,xi,mode,freq_khz,ipr) and OUTPUT with .json (every parameter).",
      "ipr-map"};
  tool::describe_common(app);
  std::string disorder = "A", xi_text = "0.1:1", q_text = "0.2,0.5,0.8", output = "ipr-map.csv", solver = "fast";
  std::string method = "lapack";
  IprMapConfig config;
  RunOptions run;
  tool::SelectionOptions selection;
  bool quiet = false;
  app.add_option("--disorder", disorder, "h | A | RDM1 | RDM2 (homogeneous, Anderson, random dimer 1/2)")
      ->capture_default_str();
  app.add_option("--xi", xi_text, "size ratios R2/R1 in (0,1]: start:stop[:step] (step 0.01) or a,b,c")
      ->capture_default_str();
  app.add_option("--q", q_text, "probabilities of type 1 (or of dimer 11 / 12) in [0,1]: list or range")
      ->capture_default_str();
  tool::add_integer(app, "--N", config.chain.N, "beads per chain (>= 2)");
  app.add_option("--F0", config.chain.F0, "static precompression [N], > 0")->capture_default_str();
  app.add_option("--R1", config.chain.R1, "radius of type-1 beads [m]; type 2 has xi*R1 (steel beads, steel walls)")
      ->capture_default_str();
  tool::add_integer(app, "--realizations", config.realizations, "chains averaged per (q, xi)");
  tool::add_integer(app, "--seed", config.chain.seed, "random seed; realization r of seed s is always the same chain");
  tool::add_integer(app, "--threads", run.threads, "worker threads (0 = all cores); results do not depend on it");
  app.add_option("--solver", solver,
                 "mode solver: fast (eigenvalues + one twisted factorization per mode, no eigenvector matrix; IPRs as "
                 "LAPACK's to 1e-10 outside tight eigenvalue clusters) | lapack (= lapack-stevd) | lapack-stevr | "
                 "lapack-stemr | lapack-stevd | lapack-steqr")
      ->capture_default_str();
  app.add_option("--output", output, "CSV file to write (the JSON goes beside it)")->capture_default_str();
  tool::add_selection_options(app, selection, "partial spectra: ");
  app.add_option("--method", method, "partial spectra: lapack | bisect | arpack | slepc (arpack/slepc: one thread)")
      ->capture_default_str();
  app.add_option("--bin-khz", config.bin_khz,
                 "average in frequency bins of this width [kHz] instead of by mode number: "
                 "columns disorder,q,xi,freq_lo_khz,freq_hi_khz,modes,ipr (empty bins: modes 0, ipr nan)");
  tool::ChainOptions beads;  // --types/--type-masses/--polydisperse (with --disorder as their rule)
  tool::add_bead_distribution_options(app, beads);
  app.add_flag("--quiet", quiet, "no progress line on stderr");

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("ipr-map", argc, argv);
    config.chain.disorder = parse_disorder(disorder);
    config.xi_values = parse_number_list(xi_text, "--xi", 0.01);
    config.q_values = parse_number_list(q_text, "--q", 0.1);
    if (config.chain.N > 100000000)
      throw InvalidInput("N", " " + std::to_string(config.chain.N) + ": more than 1e8 beads");
    if (run.threads < 0) throw InvalidInput("threads", " " + std::to_string(run.threads) + ": must be >= 0");
    if (solver != "fast" && solver != "lapack" && !solver.starts_with("lapack-"))
      throw InvalidInput("--solver", " '" + solver + "': expected fast, lapack or lapack-<stevr|stemr|stevd|steqr>");
    config.spectrum.method = solver == "fast" ? SpectrumMethod::fast : SpectrumMethod::lapack;
    if (solver.starts_with("lapack-")) config.spectrum.driver = parse_lapack_driver(solver.substr(7));
    config.selection = tool::parse_selection(selection);
    if (selection.given()) {
      config.spectrum.method = parse_spectrum_method(method);
      if (config.spectrum.method == SpectrumMethod::fast)
        throw InvalidInput("--method", " fast: computes every mode; use lapack, bisect or arpack with --near/--window");
    } else if (app.count("--method") > 0) {
      throw InvalidInput("--method", ": only with --near/--count or --window (the full map uses --solver)");
    }
    beads.disorder = disorder;
    if ((config.chain.distribution = tool::bead_distribution(beads)))
      config.q_values = config.xi_values = {std::numeric_limits<double>::quiet_NaN()};  // one cell
    validate(config);
    const tool::OutputClaim claim(tool::prefix_of(output), meta.command());
    check_writable(output);
    const std::string json_path = tool::json_path_for(output);
    check_writable(json_path);

    ProgressMeter progress(config.q_values.size() * config.xi_values.size() * config.realizations, "ipr-map",
                           quiet ? 0 : -1);
    run.progress = &progress;
    const auto cells = compute_ipr_map(config, run);
    progress.finish();

    AtomicFile csv(output);
    const std::string name = !config.chain.distribution ? to_string(config.chain.disorder)
                             : config.chain.distribution->kind == BeadDistribution::Kind::types ? "types"
                                                                                                : "polydisperse";
    if (selection.given()) {  // modes differ between chains: one row per mode of each realization
      CsvWriter table(csv.stream(), {"disorder", "q", "xi", "realization", "mode", "freq_khz", "ipr"});
      for (const auto& cell : cells)
        for (std::size_t j = 0; j < cell.mode.size(); ++j)
          table.row(name, cell.q, cell.xi, static_cast<std::size_t>(cell.realization[j]), cell.mode[j],
                    cell.freq_khz[j], cell.ipr[j]);
    } else if (config.bin_khz > 0) {  // modes = modes of all realizations in the bin
      CsvWriter table(csv.stream(), {"disorder", "q", "xi", "freq_lo_khz", "freq_hi_khz", "modes", "ipr"});
      for (const auto& cell : cells)
        for (std::size_t b = 0; b < cell.bin_modes.size(); ++b)
          table.row(name, cell.q, cell.xi, static_cast<double>(b) * config.bin_khz,
                    static_cast<double>(b + 1) * config.bin_khz, cell.bin_modes[b], cell.bin_ipr[b]);
    } else {
      CsvWriter table(csv.stream(), {"disorder", "q", "xi", "mode", "freq_khz", "ipr"});
      for (const auto& cell : cells)
        for (std::size_t k = 0; k < config.chain.N; ++k)
          table.row(name, cell.q, cell.xi, k + 1, cell.freq_khz[k], cell.ipr[k]);
    }
    meta["parameters"] = {{"disorder", name},
                          {"xi", config.xi_values},
                          {"q", config.q_values},
                          {"N", config.chain.N},
                          {"F0_N", config.chain.F0},
                          {"R1_m", config.chain.R1},
                          {"material",
                           {{"E_Pa", config.chain.material.young},
                            {"nu", config.chain.material.poisson},
                            {"rho_kg_m3", config.chain.material.density}}},
                          {"walls", "flat, same material as the beads"},
                          {"realizations", config.realizations},
                          {"seed", config.chain.seed},
                          {"threads", resolve_threads(run.threads)},
                          {"solver", solver}};
    if (config.chain.distribution) meta["parameters"]["beads"] = describe(*config.chain.distribution);
    if (!selection.given()) {
      meta["averaging"] = config.bin_khz > 0 ? "frequency-bin" : "mode";
      if (config.bin_khz > 0) meta["bin_khz"] = config.bin_khz;
    }
    if (selection.given())
      meta["selection"] = {{"method", method},
                           {"near_khz", selection.near ? nlohmann::json(*selection.near) : nlohmann::json(nullptr)},
                           {"count", selection.count ? nlohmann::json(*selection.count) : nlohmann::json(nullptr)},
                           {"window_khz",
                            selection.window ? nlohmann::json(*selection.window) : nlohmann::json(nullptr)}};
    std::size_t solved = 0, clustered = 0;
    for (const auto& cell : cells) solved += cell.solved_modes, clustered += cell.clustered_modes;
    meta["clustered"] = {{"relative_gap", cluster_relative_gap},
                         {"modes", clustered},
                         {"fraction", solved > 0 ? static_cast<double>(clustered) / static_cast<double>(solved) : 0.0}};
    meta["output"] = output;
    meta.write(json_path, {&csv});
  });
}
