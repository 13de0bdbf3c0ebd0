// spectrum: linear modes of one chain — frequency [kHz] and displacement IPR by increasing
// frequency: all of them, or the K nearest a frequency (--near/--count) or those in a band
// (--window), by any solver of granular::spectrum. Under `mpirun -np P ... --method slepc` the
// matrix rows are spread over the ranks; rank 0 writes.
#include <algorithm>
#include <string>

#include "common/chain_options.hpp"
#include "common/metadata.hpp"
#include "common/output_claim.hpp"
#include "common/spectrum_options.hpp"
#include "common/tool_main.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/study/spectrum_file.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Linear spectrum of one precompressed chain: columns mode,freq_khz,ipr (modes numbered 1..N by\n"
      "increasing frequency; IPR = sum v^4/(sum v^2)^2 of the displacement mode). Every mode by default;\n"
      "--near KHZ --count K: the K modes nearest KHZ; --window F1:F2: every mode in [F1, F2] kHz.\n"
      "Writes OUTPUT and OUTPUT with .json (parameters, band edges, solver report).",
      "spectrum"};
  tool::describe_common(app);
  tool::ChainOptions chain_options;
  tool::add_chain_options(app, chain_options);
  tool::SelectionOptions selection_options;
  tool::add_selection_options(app, selection_options, "");
  std::string method = "lapack", output = "spectrum.csv", vectors_file, dump_matrix;
  SpectrumConfig config;
  bool quiet = false, clusters = false;
  app.add_option("--method", method,
                 "every mode: lapack (dstevd) | fast (no eigenvectors); --near/--window: lapack (dstemr by index) |\n"
                 "bisect (Sturm bisection + inverse iteration, the fastest for long chains) | arpack | slepc\n"
                 "(shift-invert; slepc runs on every mpirun rank)")
      ->capture_default_str();
  app.add_option("--tolerance", config.tolerance, "ARPACK/SLEPc Ritz tolerance (0 = tightest default)")
      ->capture_default_str();
  tool::add_integer(app, "--lanes", config.lanes,
                    "bisect: eigenvectors computed together, 1..64 (memory 2 N x lanes doubles)");
  app.add_option("--vectors", vectors_file, "also write the eigenvectors to this HDF5 file");
  app.add_option("--dump-matrix", dump_matrix,
                 "also write the dynamical matrix as raw little-endian doubles PREFIX.diag.f64 (N) and "
                 "PREFIX.offdiag.f64 (N-1) [1/s^2], to compare with other codes on the very same matrix");
  app.add_option("--output", output, "CSV file to write (the JSON goes beside it)")->capture_default_str();
  app.add_flag("--clusters", clusters,
               "add a column clustered: 1 for a mode in a near-degenerate cluster (relative gap < 1e-10), whose "
               "IPR depends on the basis chosen inside it");
  app.add_flag("--quiet", quiet, "no notes on stderr");

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("spectrum", argc, argv);
    config.method = parse_spectrum_method(method);
    config.vectors = !vectors_file.empty();
    const ModeSelection selection = tool::parse_selection(selection_options);
    validate(config, selection);
    DynamicalMatrix d;
    nlohmann::json chain_description;
    {  // the chain is only needed for the matrix; free it before a large solve
      const tool::SelectedChain selected = tool::build_chain(chain_options);
      chain_description = selected.description;
      d = dynamical_matrix(selected.chain);
    }
    validate(selection, d.size());
    const bool writer = MpiContext::instance().root();
    const tool::OutputClaim claim(tool::prefix_of(output), meta.command());
    if (writer) {
      check_writable(output);
      check_writable(tool::json_path_for(output));
      if (!vectors_file.empty()) check_writable(vectors_file);
    }
    if (writer && !dump_matrix.empty()) {
      AtomicFile diag(dump_matrix + ".diag.f64"), off(dump_matrix + ".offdiag.f64");
      diag.stream().write(reinterpret_cast<const char*>(d.diagonal.data()),
                          static_cast<std::streamsize>(8 * d.diagonal.size()));
      off.stream().write(reinterpret_cast<const char*>(d.off_diagonal.data()),
                         static_cast<std::streamsize>(8 * d.off_diagonal.size()));
      diag.commit();
      off.commit();
    }
    const Spectrum result = spectrum(d, selection, config);
    if (!writer) return;

    if (!quiet && result.size() == 0) std::fprintf(stderr, "spectrum: note: no modes in the window\n");
    AtomicFile csv(output);
    if (clusters) {
      CsvWriter table(csv.stream(), {"mode", "freq_khz", "ipr", "clustered"});
      for (std::size_t j = 0; j < result.size(); ++j)
        table.row(result.mode[j], result.freq_khz[j], result.ipr[j], int{result.clustered[j]});
    } else {
      CsvWriter table(csv.stream(), {"mode", "freq_khz", "ipr"});
      for (std::size_t j = 0; j < result.size(); ++j) table.row(result.mode[j], result.freq_khz[j], result.ipr[j]);
    }
    const auto flagged = static_cast<std::size_t>(std::count(result.clustered.begin(), result.clustered.end(), 1));
    meta["clustered"] = {{"relative_gap", cluster_relative_gap}, {"modes", flagged}};
    meta["chain"] = chain_description;
    meta["method"] = method;
    meta["solver"] = {{"method", result.info.method}, {"fallbacks", result.info.fallbacks}};
    if (selection.kind != ModeSelection::Kind::all) {
      meta["selection"] = selection.kind == ModeSelection::Kind::nearest
                              ? nlohmann::json{{"near_khz", selection.near_khz}, {"count", selection.count}}
                              : nlohmann::json{{"window_khz", {selection.lo_khz, selection.hi_khz}}};
      meta["solver"].update({{"restarts", result.info.restarts},
                             {"candidates", result.info.candidates},
                             {"max_relative_residual", result.info.max_residual},
                             {"tolerance", config.tolerance},
                             {"mpi_ranks", MpiContext::instance().size()}});
    }
    if (chain_description.contains("xi") && chain_options.f0 > 0) {
      const BandEdges e = band_edges(steel, chain_options.r1, chain_options.xi, chain_options.f0);
      meta["band_edges_khz"] = {
          {"f1", e.f1 * 1e-3}, {"f2", e.f2 * 1e-3}, {"fb1", e.fb1 * 1e-3}, {"fb2", e.fb2 * 1e-3}, {"fb3", e.fb3 * 1e-3}};
    }
    meta["output"] = output;
    if (!vectors_file.empty()) {
      write_spectrum_hdf5(vectors_file, result, d);
      meta["vectors"] = vectors_file;
    }
    meta.write(tool::json_path_for(output), {&csv});
  });
}
