// spectrum: linear modes of one chain — frequency [kHz] and displacement IPR by increasing
// frequency: all of them (LAPACK), or the K nearest a frequency (--near/--count) or those in a
// band (--window) by LAPACK, bisection, ARPACK or SLEPc. Under `mpirun -np P ... --method slepc`
// the matrix rows are spread over the ranks; rank 0 writes.
#include <cstdio>
#include <optional>
#include <string>

#include "common/chain_options.hpp"
#include "common/metadata.hpp"
#include "common/tool_main.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/linear/mode_ipr_solver.hpp"
#include "granular/linear/partial_spectrum.hpp"
#include "granular/linear/shift_invert_eigensolvers.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{"Linear spectrum of one precompressed chain: columns mode,freq_khz,ipr (modes numbered 1..N by\n"
               "increasing frequency; IPR = sum v^4/(sum v^2)^2 of the displacement mode). Every mode by default;\n"
               "--near KHZ --count K: the K modes nearest KHZ; --window F1:F2: every mode in [F1, F2] kHz.\n"
               "Writes OUTPUT and OUTPUT with .json (parameters, band edges, solver report).",
               "spectrum"};
  tool::describe_common(app);
  tool::ChainOptions chain_options;
  tool::add_chain_options(app, chain_options);
  std::string method = "lapack", output = "spectrum.csv", vectors_file, dump_matrix;
  std::optional<double> near;
  std::optional<long> count;
  std::optional<std::string> window;
  double tolerance = 0;
  long lanes = 8;
  bool quiet = false;
  app.add_option("--near", near, "target frequency [kHz] (with --count)");
  app.add_option("--count", count, "number of modes nearest --near (1 <= K <= N)");
  app.add_option("--window", window, "F1:F2: every mode with F1 <= f <= F2 [kHz]");
  app.add_option("--method", method,
                 "lapack (full: dstevd; partial: dstemr by index) | bisect (Sturm bisection + inverse iteration,\n"
                 "the fastest for long chains) | arpack | slepc (shift-invert; slepc runs on every mpirun rank)")
      ->capture_default_str();
  app.add_option("--tolerance", tolerance, "ARPACK/SLEPc Ritz tolerance (0 = tightest default)")->capture_default_str();
  app.add_option("--lanes", lanes, "bisect: eigenvectors computed together, 1..64 (memory 2 N x lanes doubles)")
      ->capture_default_str();
  app.add_option("--vectors", vectors_file, "partial spectra: also write the eigenvectors to this HDF5 file");
  app.add_option("--dump-matrix", dump_matrix,
                 "also write the dynamical matrix as raw little-endian doubles PREFIX.diag.f64 (N) and "
                 "PREFIX.offdiag.f64 (N-1) [1/s^2], to compare with other codes on the very same matrix");
  app.add_option("--output", output, "CSV file to write (the JSON goes beside it)")->capture_default_str();
  app.add_flag("--quiet", quiet, "no notes on stderr");

  const int code = tool::run(app, argc, argv, [&] {
    tool::Metadata meta("spectrum", argc, argv);
    const PartialMethod m = parse_partial_method(method);
    const bool partial = near || count || window;
    if (!partial && m != PartialMethod::lapack)
      throw InvalidInput("--method " + method + ": computes partial spectra; give --near/--count or --window");
    if (!partial && !vectors_file.empty()) throw InvalidInput("--vectors: only with --near/--count or --window");
    if (lanes < 1 || lanes > 64) throw InvalidInput("--lanes " + std::to_string(lanes) + ": must be in 1..64");
    const std::optional<SpectrumSelection> selection =
        partial ? std::optional(parse_selection(near, count, window)) : std::nullopt;
    SymTridiagonal d;
    std::vector<double> s;
    nlohmann::json chain_description;
    {  // the chain is only needed for the matrix and m^{-1/2}; free it before a large solve
      const tool::SelectedChain selected = tool::build_chain(chain_options);
      chain_description = selected.description;
      d = dynamical_matrix(selected.chain);
      s = inverse_sqrt_mass(selected.chain.inverse_mass);
    }
    if (selection) validate(*selection, d.size());
    const bool writer = mpi_rank() == 0;
    if (writer) {
      check_writable(output);
      check_writable(tool::json_path_for(output));
      if (!vectors_file.empty()) check_writable(vectors_file);
    }
    if (m == PartialMethod::slepc) initialize_slepc(nullptr, nullptr);
    if (writer && !dump_matrix.empty()) {
      AtomicFile diag(dump_matrix + ".diag.f64"), off(dump_matrix + ".offdiag.f64");
      diag.stream().write(reinterpret_cast<const char*>(d.diagonal.data()), static_cast<std::streamsize>(8 * d.diagonal.size()));
      off.stream().write(reinterpret_cast<const char*>(d.off_diagonal.data()),
                         static_cast<std::streamsize>(8 * d.off_diagonal.size()));
      diag.commit();
      off.commit();
    }

    PartialSpectrum result;
    if (selection) {
      PartialSpectrumConfig config;
      config.method = m;
      config.keep_vectors = !vectors_file.empty();
      config.tolerance = tolerance;
      config.lanes = static_cast<std::size_t>(lanes);
      result = partial_spectrum(d, s, *selection, config);
    } else {
      std::vector<double> omega2, ipr;
      LapackModeIpr solver;
      solver.solve(d, s, omega2, ipr);
      for (std::size_t k = 0; k < omega2.size(); ++k) {
        result.mode.push_back(k + 1);
        result.omega2.push_back(omega2[k]);
        result.freq_khz.push_back(frequency_khz(omega2[k]));
        result.ipr.push_back(ipr[k]);
      }
      result.method = "lapack-stevd (full spectrum)";
    }
    if (!writer) return;

    if (!quiet && result.size() == 0) std::fprintf(stderr, "spectrum: note: no modes in the window\n");
    double worst = 0;
    for (double r : result.residual) worst = std::max(worst, r);
    AtomicFile csv(output);
    CsvWriter table(csv.stream(), {"mode", "freq_khz", "ipr"});
    for (std::size_t j = 0; j < result.size(); ++j) table.row(result.mode[j], result.freq_khz[j], result.ipr[j]);
    meta["chain"] = chain_description;
    meta["method"] = method;
    if (selection) {
      meta["selection"] = selection->kind == SpectrumSelection::Kind::nearest
                              ? nlohmann::json{{"near_khz", selection->near_khz}, {"count", selection->count}}
                              : nlohmann::json{{"window_khz", {selection->lo_khz, selection->hi_khz}}};
      meta["solver"] = {{"method", result.method}, {"restarts", result.restarts}, {"candidates", result.candidates},
                        {"max_relative_residual", worst}, {"tolerance", tolerance}, {"mpi_ranks", mpi_size()}};
    } else {
      meta["solver"] = {{"method", result.method}};
    }
    if (chain_description.contains("xi") && chain_options.f0 > 0) {
      const BandEdges e = band_edges(steel, chain_options.r1, chain_options.xi, chain_options.f0);
      meta["band_edges_khz"] = {{"f1", e.f1 * 1e-3}, {"f2", e.f2 * 1e-3}, {"fb1", e.fb1 * 1e-3},
                                {"fb2", e.fb2 * 1e-3}, {"fb3", e.fb3 * 1e-3}};
    }
    meta["output"] = output;
    if (!vectors_file.empty()) {
      write_partial_spectrum_hdf5(vectors_file, result, s);
      meta["vectors"] = vectors_file;
    }
    csv.commit();
    meta.write(tool::json_path_for(output));
  });
  finalize_slepc();
  return code;
}
