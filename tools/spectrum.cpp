// spectrum: linear modes of one chain — frequency [kHz] and displacement IPR by increasing
// frequency: all of them, or the K nearest a frequency (--near/--count) or those in a band
// (--window), by any solver of granular::spectrum. Under `mpirun -np P ... --method slepc` the
// matrix rows are spread over the ranks; rank 0 writes.
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/chain_options.hpp"
#include "common/outputs.hpp"
#include "common/spectrum_options.hpp"
#include "common/tool_main.hpp"
#include "granular/files/spectrum_file.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/hdf5_file.hpp"
#include "granular/linear/spectrum_parameters.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/study/solve_estimate.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Linear spectrum of one precompressed chain: columns mode,freq_khz,ipr (modes numbered 1..N by\n"
      "increasing frequency; IPR = sum v^4/(sum v^2)^2 of the displacement mode). Every mode by default;\n"
      "--near KHZ --count K: the K modes nearest KHZ; --window F1:F2: every mode in [F1, F2] kHz.\n"
      "Writes PREFIX.csv and PREFIX.json (parameters, band edges, solver report); PREFIX from --output.",
      "spectrum"};
  tool::describe_common(app);
  tool::ChainOptions chain_options;
  tool::add_chain_options(app, chain_options);
  ModeSelectionChoices selection_choices;
  tool::add_selection_options(app, selection_choices, "");
  std::string output = "spectrum", vectors_file, dump_matrix;
  SpectrumConfig config;
  bool quiet = false, clusters = false;
  tool::add_parameters(app, config, spectrum_parameters(), {.except = {"vectors"}});  // a file here
  app.add_option("--vectors", vectors_file, "also write the eigenvectors to this HDF5 file");
  app.add_option("--dump-matrix", dump_matrix,
                 "also write the dynamical matrix as raw little-endian doubles PREFIX.diag.f64 (N) and "
                 "PREFIX.offdiag.f64 (N-1) [1/s^2], to compare with other codes on the very same matrix");
  tool::add_output_option(app, output);
  app.add_flag("--clusters", clusters,
               "add a column clustered: 1 for a mode in a near-degenerate cluster (relative gap < 1e-10), whose "
               "IPR depends on the basis chosen inside it");
  app.add_flag("--quiet", quiet, "no notes on stderr");

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("spectrum", argc, argv);
    config.vectors = !vectors_file.empty();
    const SpectrumRequest request{choose_modes(selection_choices), config};
    const ModeSelection& selection = request.selection;
    validate(request.config, selection);
    if (config.vectors) load_hdf5_writer();  // before the solve, not after it
    const ChainRecipe recipe = tool::chain_recipe(chain_options);
    validate(recipe);  // the matrix is stored: at most 1e8 beads
    // Read a piece at a time: a drawn chain's matrix is built without the chain's arrays beside it.
    StreamedChain chain = stream_chain(recipe, chain_realization(chain_options), tool::radius_options(chain_options));
    tool::warn(chain.warnings);
    if (selection.kind != ModeSelection::Kind::all) {
      const bool near = selection.kind == ModeSelection::Kind::nearest;
      tool::warn({frequency_warning(near ? "--near" : "--window", near ? selection.near_khz : selection.lo_khz,
                                    chain.highest_frequency_khz)});
    }
    const DynamicalMatrix d = dynamical_matrix(*chain.beads);
    chain.beads.reset();  // what a stored chain's source holds, freed before a large solve
    validate(selection, d.size());
    // Refused before the output is claimed and before anything of size N² exists.
    if (const std::string problem = full_spectrum_problem(d.size(), request.config, selection); !problem.empty())
      throw InvalidInput("N", " " + std::to_string(d.size()) + ": " + problem +
                                  "; what fits: --method fast (every frequency and IPR, no eigenvectors), or selected "
                                  "modes with --near F --count K or --window LO:HI and --method bisect");
    const bool writer = MpiContext::instance().root();
    const std::string csv_path = output + ".csv", json_path = output + ".json";
    const auto claim = tool::claim_output(output, meta.command());
    if (writer) {
      check_writable(csv_path);
      check_writable(json_path);
      if (!vectors_file.empty()) check_writable(vectors_file);
    }
    if (writer && !dump_matrix.empty()) write_matrix_dump(dump_matrix, d);
    // A solve of every mode is one silent call: say how long it will be when that is more than a few seconds.
    const SolveEstimate estimate =
        quiet || !writer ? SolveEstimate{} : estimate_every_mode_solve(d, request.config, selection);
    const bool announced = estimate.seconds > announced_solve_seconds;
    if (announced) std::fprintf(stderr, "spectrum: %s\n", describe(estimate).c_str());
    const auto start = std::chrono::steady_clock::now();
    const Spectrum result = spectrum(d, selection, request.config);
    if (announced)
      std::fprintf(stderr, "spectrum: the solve took %.0f s\n",
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (!writer) return;

    if (!quiet && result.size() == 0) std::fprintf(stderr, "spectrum: note: no modes in the window\n");
    AtomicFile csv(csv_path);
    write_spectrum_csv(csv.stream(), result, clusters);
    meta.merge(describe_spectrum(result, request, chain.description, recipe.material));
    meta["output"] = csv_path;
    std::vector<PendingOutput*> outputs{&csv};
    std::unique_ptr<Hdf5File> vectors;
    if (!vectors_file.empty()) {
      vectors = write_spectrum_hdf5(vectors_file, result, d);
      outputs.push_back(vectors.get());
      meta["vectors"] = vectors_file;
    }
    meta.write(json_path, outputs);
  });
}
