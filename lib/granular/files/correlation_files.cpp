#include "granular/files/correlation_files.hpp"

#include <nlohmann/json.hpp>
#include "granular/io/csv_writer.hpp"

namespace granular {

void write_correlations_csv(std::ostream& out, const CorrelationResult& result) {
  CsvWriter table(out, {"distance", "rho_mean", "rho_std", "rho_theory"});
  for (std::size_t d = 0; d < result.mean.size(); ++d)
    table.row(d, result.mean[d], result.deviation[d], result.theory[d]);
}

nlohmann::json describe_correlations(const CorrelationConfig& config, const CorrelationResult& result) {
  nlohmann::json meta;
  const auto* beads = config.chain.as<BeadDistribution>();
  meta["parameters"] = {{"disorder", to_string(beads ? beads->rule : config.chain.draw().disorder)},
                        {"N", config.chain.N},
                        {"realizations", config.realizations},
                        {"seed", config.chain.seed},
                        {"max_distance", config.max_distance}};
  if (beads) meta["parameters"]["beads"] = describe(*beads);
  else meta["parameters"]["q"] = config.chain.draw().q;  // a bead distribution has no q
  meta["correlated"] = beads ? "bead mass" : "bead type (type 1 -> 0, type 2 -> 1)";
  meta["realizations_used"] = result.used;
  return meta;
}

}  // namespace granular
