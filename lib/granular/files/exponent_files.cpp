#include "granular/files/exponent_files.hpp"

#include <nlohmann/json.hpp>

#include "granular/parallel/mpi_context.hpp"
#include "granular/study/exponent_choices.hpp"

namespace granular {

std::vector<std::string> ExponentPaths::all() const {
  std::vector<std::string> paths{csv, curves, profiles, json};
  if (!paper.empty()) paths.push_back(paper);
  return paths;
}

ExponentPaths exponent_paths(const std::string& prefix, bool paper) {
  return {.csv = prefix + ".csv",
          .curves = prefix + "-curves.csv",
          .profiles = prefix + "-profiles.csv",
          .json = prefix + ".json",
          .paper = paper ? prefix + "-paper.csv" : ""};
}

std::vector<std::unique_ptr<AtomicFile>> write_exponent_files(const ExponentPaths& paths,
                                                              const std::vector<ExponentCell>& cells,
                                                              const std::vector<CellComparison>& comparison) {
  std::vector<std::unique_ptr<AtomicFile>> files;
  const auto open = [&](const std::string& path) -> std::ostream& {
    return files.emplace_back(std::make_unique<AtomicFile>(path))->stream();
  };
  write_exponents_csv(open(paths.csv), cells);
  write_curves_csv(open(paths.curves), cells);
  write_profiles_csv(open(paths.profiles), cells);
  if (!paths.paper.empty()) write_comparison_csv(open(paths.paper), comparison);
  return files;
}

nlohmann::json describe_table_parameters(const ExponentTableConfig& config, int threads) {
  return {{"chains", chain_list(config)},
          {"F0", config.precompressions},
          {"ic", kick_list(config)},
          {"threads", threads},
          {"mpi_ranks", MpiContext::instance().size()}};
}

nlohmann::json describe_cells(const std::vector<ExponentCell>& cells) {
  nlohmann::json all = nlohmann::json::array();
  for (const auto& c : cells) {
    nlohmann::json one = describe(c.definition);
    one["failed_excluded"] = c.summary.excluded;
    if (const auto& e = c.summary.exponents)
      one["exponents"] = {{"gamma_site", to_json(e->gamma_site)},
                          {"gamma_centroid", to_json(e->gamma_centroid)},
                          {"eta", to_json(e->eta)}};
    if (!c.summary.mle.mean.empty()) one["mle_at_T"] = to_json(mle_at_end(c.summary));
    one["chain"] = chain_name(c);
    all.push_back(one);
  }
  return all;
}

nlohmann::json describe_exponent_study(const ExponentTableConfig& config, int threads,
                                       const std::vector<ExponentCell>& cells, const nlohmann::json& step_rule,
                                       const nlohmann::json& resumed) {
  nlohmann::json j;
  j["parameters"] = describe_table_parameters(config, threads);
  j["cases"] = describe_cells(cells);
  j["time_step_rule"] = step_rule;
  if (!resumed.is_null()) j["resumed_checkpoint"] = resumed;
  return j;
}

}  // namespace granular
