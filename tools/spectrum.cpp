// spectrum: every linear mode of one chain — frequency [kHz] and displacement IPR — by
// increasing frequency, with the chain's analytic band edges in the JSON.
#include <string>

#include "common/chain_options.hpp"
#include "common/metadata.hpp"
#include "common/tool_main.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr_solver.hpp"
#include "granular/linear/mode_ipr.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{"Linear spectrum of one precompressed chain: columns mode,freq_khz,ipr (modes by increasing\n"
               "frequency, IPR = sum v^4/(sum v^2)^2 of the displacement mode). Writes OUTPUT and OUTPUT with .json.",
               "spectrum"};
  tool::describe_common(app);
  tool::ChainOptions chain_options;
  tool::add_chain_options(app, chain_options);
  std::string method = "lapack", output = "spectrum.csv";
  app.add_option("--method", method, "eigen-solver: lapack (full spectrum, dstevd)")->capture_default_str();
  app.add_option("--output", output, "CSV file to write (the JSON goes beside it)")->capture_default_str();

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("spectrum", argc, argv);
    if (method != "lapack") throw InvalidInput("--method '" + method + "': expected lapack");
    auto selected = tool::build_chain(chain_options);
    check_writable(output);
    const std::string json_path = tool::json_path_for(output);
    check_writable(json_path);

    const Chain& chain = selected.chain;
    std::vector<double> omega2, ipr;
    LapackModeIpr solver;
    solver.solve(dynamical_matrix(chain), inverse_sqrt_mass(chain.inverse_mass), omega2, ipr);

    AtomicFile csv(output);
    CsvWriter table(csv.stream(), {"mode", "freq_khz", "ipr"});
    for (std::size_t k = 0; k < omega2.size(); ++k) table.row(k + 1, frequency_khz(omega2[k]), ipr[k]);
    meta["chain"] = selected.description;
    meta["method"] = method;
    if (selected.description.contains("xi") && chain.precompression > 0) {
      const BandEdges e = band_edges(steel, chain_options.r1, chain_options.xi, chain.precompression);
      meta["band_edges_khz"] = {{"f1", e.f1 * 1e-3}, {"f2", e.f2 * 1e-3}, {"fb1", e.fb1 * 1e-3},
                                {"fb2", e.fb2 * 1e-3}, {"fb3", e.fb3 * 1e-3}};
    }
    meta["output"] = output;
    csv.commit();
    meta.write(json_path);
  });
}
