#include "granular/files/ipr_map_files.hpp"

#include <nlohmann/json.hpp>
#include "granular/io/csv_writer.hpp"
#include "granular/model/chain_recipe.hpp"

namespace granular {

void write_ipr_map_csv(std::ostream& out, const IprMapConfig& config, const std::vector<IprMapCell>& cells) {
  const std::string name = source_name(config.chain);
  if (config.selection.kind != ModeSelection::Kind::all) {  // modes differ between chains
    CsvWriter table(out, {"disorder", "q", "xi", "realization", "mode", "freq_khz", "ipr"});
    for (const auto& cell : cells)
      for (std::size_t j = 0; j < cell.mode.size(); ++j)
        table.row(name, cell.q, cell.xi, static_cast<std::size_t>(cell.realization[j]), cell.mode[j], cell.freq_khz[j],
                  cell.ipr[j]);
  } else if (config.bin_khz > 0) {  // modes = modes of all realizations in the bin
    CsvWriter table(out, {"disorder", "q", "xi", "freq_lo_khz", "freq_hi_khz", "modes", "ipr"});
    for (const auto& cell : cells)
      for (std::size_t b = 0; b < cell.bin_modes.size(); ++b)
        table.row(name, cell.q, cell.xi, static_cast<double>(b) * config.bin_khz,
                  static_cast<double>(b + 1) * config.bin_khz, cell.bin_modes[b], cell.bin_ipr[b]);
  } else {
    CsvWriter table(out, {"disorder", "q", "xi", "mode", "freq_khz", "ipr"});
    for (const auto& cell : cells)
      for (std::size_t k = 0; k < config.chain.N; ++k)
        table.row(name, cell.q, cell.xi, k + 1, cell.freq_khz[k], cell.ipr[k]);
  }
}

nlohmann::json describe_ipr_map(const IprMapConfig& config, const std::vector<IprMapCell>& cells, int threads) {
  const ChainRecipe& chain = config.chain;
  nlohmann::json meta;
  meta["parameters"] = {{"disorder", source_name(config.chain)},
                        {"xi", config.xi_values},
                        {"q", config.q_values},
                        {"N", chain.N},
                        {"F0_N", chain.F0},
                        {"R1_m", chain.R1},
                        {"material", describe(chain.material)},
                        {"walls", walls_description(chain.walls)},
                        {"realizations", config.realizations},
                        {"seed", chain.seed},
                        {"threads", threads},
                        {"solver", config.solver}};
  if (const auto* beads = chain.as<BeadDistribution>()) meta["parameters"]["beads"] = describe(*beads);
  if (const auto* quasi = chain.as<Quasiperiodic>()) meta["parameters"]["quasiperiodic"] = describe(*quasi);
  const ModeSelection& s = config.selection;
  if (s.kind == ModeSelection::Kind::all) {
    meta["averaging"] = config.bin_khz > 0 ? "frequency-bin" : "mode";
    if (config.bin_khz > 0) meta["bin_khz"] = config.bin_khz;
  } else {
    const bool by_window = s.kind == ModeSelection::Kind::window;
    meta["selection"] = {{"method", config.method.empty() ? "lapack" : config.method},
                         {"near_khz", by_window ? nlohmann::json(nullptr) : nlohmann::json(s.near_khz)},
                         {"count", by_window ? nlohmann::json(nullptr) : nlohmann::json(s.count)},
                         {"window_khz", by_window ? nlohmann::json{s.lo_khz, s.hi_khz} : nlohmann::json(nullptr)}};
  }
  std::size_t solved = 0, clustered = 0;
  for (const auto& cell : cells) solved += cell.solved_modes, clustered += cell.clustered_modes;
  meta["clustered"] = {{"relative_gap", cluster_relative_gap},
                       {"modes", clustered},
                       {"fraction", solved > 0 ? static_cast<double>(clustered) / static_cast<double>(solved) : 0.0}};
  return meta;
}

}  // namespace granular
