// partial-spectrum (temporary; to be folded into `spectrum`): the K modes of one chain nearest a
// frequency, or all modes in a frequency window, with their IPRs, by LAPACK, ARPACK or SLEPc.
// Under `mpirun -np P ... --method slepc` the matrix rows are spread over the ranks; rank 0 writes.
#include <cstdio>
#include <optional>
#include <string>

#include "common/metadata.hpp"
#include "common/tool_main.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/linear/partial_spectrum.hpp"
#include "granular/linear/shift_invert_eigensolvers.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/configuration_file.hpp"
#include "granular/model/disorder.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{"Modes of one chain nearest a frequency (--near KHZ --count K) or inside a band (--window F1:F2),\n"
               "with their displacement IPR. Writes OUTPUT (columns mode,freq_khz,ipr) and OUTPUT with .json.",
               "partial-spectrum"};
  tool::describe_common(app);
  std::string disorder = "A", method = "lapack", output = "partial-spectrum.csv", config_file, radii_file, vectors_file;
  long long n = 100, seed = 1, realization = 0;
  double xi = 0.5, q = 0.5, f0 = 10, r1 = 4.76e-3, tolerance = 0;
  std::optional<double> near;
  std::optional<long> count;
  std::optional<std::string> window;
  bool quiet = false;
  app.add_option("--disorder", disorder, "h | A | RDM1 | RDM2")->capture_default_str();
  app.add_option("--xi", xi, "size ratio R2/R1 in (0,1]")->capture_default_str();
  app.add_option("--q", q, "probability of type 1 (or of dimer 11 / 12) in [0,1]")->capture_default_str();
  app.add_option("--N", n, "beads (>= 2)")->capture_default_str();
  app.add_option("--F0", f0, "static precompression [N], > 0")->capture_default_str();
  app.add_option("--R1", r1, "radius of type-1 beads [m]")->capture_default_str();
  app.add_option("--seed", seed, "random seed")->capture_default_str();
  app.add_option("--realization", realization, "realization number r of the seed")->capture_default_str();
  app.add_option("--config", config_file, "file with one bead type (1 or 2) per line (overrides --disorder/--q/--N)");
  app.add_option("--radii", radii_file, "file with one radius [m] per line (overrides everything above but --F0)");
  app.add_option("--near", near, "target frequency [kHz]");
  app.add_option("--count", count, "number of modes nearest --near (1 <= K <= N)");
  app.add_option("--window", window, "F1:F2: every mode with F1 <= f <= F2 [kHz]");
  app.add_option("--method", method, "lapack | arpack | slepc (slepc runs on every mpirun rank)")->capture_default_str();
  app.add_option("--tolerance", tolerance, "ARPACK/SLEPc Ritz tolerance (0 = tightest default)")->capture_default_str();
  long lanes = 8;
  app.add_option("--lanes", lanes, "bisect: eigenvectors computed together, 1..64 (memory 2 N x lanes doubles)")
      ->capture_default_str();
  app.add_option("--vectors", vectors_file, "also write the eigenvectors to this HDF5 file");
  app.add_option("--output", output, "CSV file to write (the JSON goes beside it)")->capture_default_str();
  app.add_flag("--quiet", quiet, "no notes on stderr");
  std::string dump_matrix;
  app.add_option("--dump-matrix", dump_matrix,
                 "also write the dynamical matrix as raw little-endian doubles PREFIX.diag.f64 (N) and "
                 "PREFIX.offdiag.f64 (N-1), for comparisons with other codes on the very same matrix");

  const int code = tool::run(app, argc, argv, [&] {
    tool::Metadata meta("partial-spectrum", argc, argv);
    const PartialMethod m = parse_partial_method(method);
    const SpectrumSelection selection = parse_selection(near, count, window);
    if (seed < 0) throw InvalidInput("--seed " + std::to_string(seed) + ": must be >= 0");
    if (realization < 0) throw InvalidInput("--realization " + std::to_string(realization) + ": must be >= 0");
    if (!(f0 > 0) || !std::isfinite(f0)) throw InvalidInput("--F0: the linear spectrum needs a finite F0 > 0");
    if (!(r1 > 0) || !std::isfinite(r1)) throw InvalidInput("--R1: must be finite and > 0");
    std::vector<double> radii;
    if (!radii_file.empty()) {
      radii = read_radii_file(radii_file);
    } else {
      Configuration types;
      validate_size_ratio(xi);
      if (!config_file.empty()) {
        types = read_configuration_file(config_file);
      } else {
        validate_probability(q);
        if (n < 2) throw InvalidInput("--N " + std::to_string(n) + ": a chain needs at least 2 beads");
        types = realization_configuration(parse_disorder(disorder), q, static_cast<std::size_t>(n),
                                          static_cast<std::uint64_t>(seed), static_cast<std::uint64_t>(realization));
      }
      radii = radii_of(types, r1, xi);
    }
    if (radii.size() < 2) throw InvalidInput("chain: needs at least 2 beads");
    validate(selection, radii.size());
    const bool writer = mpi_rank() == 0;
    if (writer) {
      check_writable(output);
      check_writable(tool::json_path_for(output));
      if (!vectors_file.empty()) check_writable(vectors_file);
    }
    SymTridiagonal d;
    std::vector<double> s;
    {  // the chain is only needed for the matrix and m^{-1/2}; free it before the solve
      const Chain chain = make_chain(radii, f0);
      d = dynamical_matrix(chain);
      s = inverse_sqrt_mass(chain.inverse_mass);
    }
    std::vector<double>().swap(radii);
    if (m == PartialMethod::slepc) initialize_slepc(nullptr, nullptr);
    if (writer && !dump_matrix.empty()) {
      AtomicFile diag(dump_matrix + ".diag.f64"), off(dump_matrix + ".offdiag.f64");
      diag.stream().write(reinterpret_cast<const char*>(d.diagonal.data()), static_cast<std::streamsize>(8 * d.diagonal.size()));
      off.stream().write(reinterpret_cast<const char*>(d.off_diagonal.data()),
                         static_cast<std::streamsize>(8 * d.off_diagonal.size()));
      diag.commit();
      off.commit();
    }

    PartialSpectrumConfig config;
    config.method = m;
    config.keep_vectors = !vectors_file.empty();
    config.tolerance = tolerance;
    if (lanes < 1 || lanes > 64) throw InvalidInput("--lanes " + std::to_string(lanes) + ": must be in 1..64");
    config.lanes = static_cast<std::size_t>(lanes);
    const PartialSpectrum result = partial_spectrum(d, s, selection, config);
    if (!writer) return;

    if (!quiet && result.size() == 0) std::fprintf(stderr, "partial-spectrum: note: no modes in the window\n");
    double worst = 0;
    for (double r : result.residual) worst = std::max(worst, r);
    AtomicFile csv(output);
    CsvWriter table(csv.stream(), {"mode", "freq_khz", "ipr"});
    for (std::size_t j = 0; j < result.size(); ++j) table.row(result.mode[j], result.freq_khz[j], result.ipr[j]);
    nlohmann::json sel;
    if (selection.kind == SpectrumSelection::Kind::nearest)
      sel = {{"near_khz", selection.near_khz}, {"count", selection.count}};
    else
      sel = {{"window_khz", {selection.lo_khz, selection.hi_khz}}};
    meta["parameters"] = {{"disorder", disorder}, {"xi", xi}, {"q", q}, {"N", d.size()}, {"F0_N", f0}, {"R1_m", r1},
                          {"seed", seed}, {"realization", realization}, {"config", config_file},
                          {"radii", radii_file}, {"method", method}, {"selection", sel}, {"tolerance", tolerance},
                          {"mpi_ranks", mpi_size()}};
    meta["solver"] = {{"method", result.method}, {"restarts", result.restarts}, {"candidates", result.candidates},
                      {"max_relative_residual", worst}};
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
