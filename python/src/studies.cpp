// The linear studies under granular.ipr_map, granular.localization, granular.correlations and
// granular.butterfly (and the butterfly from the dynamics, granular.dynamical_butterfly)
// (keywords, defaults, docstrings and result classes in granular/_studies.py): the library's
// study configs bound with their C++ defaults, one call per study that runs it (GIL released,
// threads, progress, Ctrl-C) and returns its arrays with the library's own JSON.
#include <nlohmann/json.hpp>
#include <string>

#include "bindings.hpp"
#include "granular/case/chain_choices.hpp"
#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/error.hpp"
#include "granular/files/correlation_files.hpp"
#include "granular/files/ipr_map_files.hpp"
#include "granular/files/localization_files.hpp"
#include "granular/model/bead_source.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/model/plausibility.hpp"
#include "granular/study/butterfly.hpp"
#include "granular/study/dynamical_butterfly.hpp"
#include "granular/study/frequency_slips.hpp"

namespace granular::python {
namespace {

/// `c` as granular/_studies.py fills it (the grid, the selection, the solver's words); `beads`: the
/// chain keywords (the two-type draw's numbers, the walls, a quasiperiodic chain or k types), by the
/// ipr-map tool's rules.
py::dict ipr_map(IprMapConfig c, const ChainChoices& beads, const PyRun& options) {
  const int thread_request = options.thread_request();
  set_solver(c);
  set_chain(c, beads);
  validate(c);
  warn(radius_warnings(c.chain, radius_names(beads, front_end_word)));  // implausible radii, as the tool warns
  warn(frequency_slips(c, front_end_word));  // near, window: Hz typed as kHz, as the tool warns

  std::vector<IprMapCell> cells;
  run_long("ipr_map", c.q_values.size() * c.xi_values.size() * c.realizations, options,
           [&](const RunOptions& run) { cells = compute_ipr_map(c, run); });

  const py::object meta = metadata("ipr_map", describe_ipr_map(c, cells, resolve_threads(thread_request)));
  py::list out_cells;
  for (auto& cell : cells)
    out_cells.append(fields("q xi freq_khz ipr mode realization bin_modes bin_ipr", cell.q, cell.xi,
                            std::move(cell.freq_khz), std::move(cell.ipr), cell.mode, cell.realization, cell.bin_modes,
                            std::move(cell.bin_ipr)));
  return fields("disorder N bin_khz q xi selection cells metadata", source_name(c.chain), c.chain.N, c.bin_khz,
                c.q_values, c.xi_values, c.selection.kind != ModeSelection::Kind::all, out_cells, meta);
}

/// `chain` (checked in granular/_studies.py), or (None) the chain of `choices` streamed a piece at
/// a time, by the localization tool's rule (stream_chain of ChainChoices).
py::dict localization(const PyChain* chain, const ChainChoices& choices, const LocalizationScanConfig& config,
                      const py::object& f, const PyRun& options) {
  const int thread_request = options.thread_request();
  // The beads as the localization tool reads them: a random realization drawn a piece at a time
  // (memory independent of N); a given chain walked as it is.
  StreamedChain s;
  if (chain) {
    s.beads = chain->recipe.beads(chain->realization);
    s.description = chain->description;
    s.highest_frequency_khz = highest_frequency_bound_khz(chain->recipe);
  } else {
    s = stream_chain(choices, front_end_word, localization_chain());
    warn(s.warnings);
  }
  const std::unique_ptr<BeadSource>& beads = s.beads;
  nlohmann::json& description = s.description;
  description["N"] = beads->size();
  const double top_khz = s.highest_frequency_khz;  // bound on the chain's frequencies (unit slips)
  validate(config);
  for (double v : config.frequency_khz)  // the first one above the chain's frequencies
    if (const std::string w = frequency_warning("f", v, top_khz); !w.empty()) {
      warn({w});
      break;
    }
  LocalizationScan scan;
  run_long("localization", beads->size() * config.frequency_khz.size(), options,
           [&](const RunOptions& run) { scan = localization_scan(*beads, config, run); });
  const py::object meta =
      metadata("localization", describe_localization(scan, description,
                                                     py::isinstance<py::str>(f) ? nlohmann::json(f.cast<std::string>())
                                                                                : nlohmann::json(config.frequency_khz),
                                                     resolve_threads(thread_request), steel));
  return fields("freq_khz lyapunov lyapunov_err loc_length resolved modes_below idos dos N metadata",
                std::move(scan.frequency_khz), std::move(scan.lyapunov), std::move(scan.lyapunov_error),
                std::move(scan.localization_length),
                std::vector<std::uint8_t>(scan.resolved.begin(), scan.resolved.end()), scan.modes_below,
                std::move(scan.idos), std::move(scan.dos), scan.beads, meta);
}

/// `c` as granular/_studies.py fills it; `beads`: the chain keywords (the two-type draw's numbers, or k
/// types or polydisperse radii instead of the two types), by the correlations tool's rule.
py::dict correlations(CorrelationConfig c, const ChainChoices& beads, const PyRun& options) {
  options.thread_request();
  set_chain(c, beads);
  validate(c);
  CorrelationResult result;
  run_long("correlations", c.realizations, options, [&](const RunOptions& run) { result = correlation_study(c, run); });
  const py::object meta = metadata("correlations", describe_correlations(c, result));
  return fields("rho_mean rho_std rho_theory used metadata", std::move(result.mean), std::move(result.deviation),
                std::move(result.theory), result.used, meta);
}

py::dict butterfly(const ButterflyConfig& c, const PyRun& options) {
  validate(c);
  std::vector<ButterflyColumn> columns;
  run_long("butterfly", c.ratios.size(), options, [&](const RunOptions& run) { columns = compute_butterfly(c, run); });
  nlohmann::json described = describe_butterfly(c, columns);
  described["threads"] = resolve_threads(options.thread_request());
  py::list out_columns;  // one dict per ratio, flattened into the tool's rows by granular/_studies.py
  for (ButterflyColumn& col : columns)
    out_columns.append(fields("ratio freq_khz ipr dimension dimension_error", col.ratio, std::move(col.freq_khz),
                              std::move(col.ipr), col.dimension.dimension, col.dimension.error));
  return fields("ratios columns metadata", c.ratios, out_columns, metadata("butterfly", described));
}

/// The integration's words and numbers are set here (the config's IntegrationConfig is not bound).
py::dict dynamical_butterfly(const DynamicalButterflyConfig& c, const PyRun& options) {
  validate(c);
  std::vector<DynamicalButterflyColumn> columns;
  run_long("dynamical_butterfly", c.ratios.size(), options,
           [&](const RunOptions& run) { columns = compute_dynamical_butterfly(c, run); });
  nlohmann::json described = describe_dynamical_butterfly(c, columns);
  described["threads"] = resolve_threads(options.thread_request());
  py::list power;  // one row per ratio, stacked by granular/_studies.py
  for (DynamicalButterflyColumn& col : columns) power.append(to_numpy(std::move(col.power)));
  std::vector<double> freq = columns.empty() ? std::vector<double>{} : columns.front().freq_khz;
  return fields("ratios freq_khz power metadata", c.ratios, std::move(freq), power,
                metadata("dynamical_butterfly", described));
}

}  // namespace

void bind_studies(py::module_& m) {
  using I = IprMapConfig;
  config_class(m, "IprMapConfig", "chain q_values xi_values realizations bin_khz selection spectrum solver method",
               &I::chain, &I::q_values, &I::xi_values, &I::realizations, &I::bin_khz, &I::selection, &I::spectrum,
               &I::solver, &I::method);
  using C = CorrelationConfig;
  config_class(m, "LocalizationScanConfig", "frequency_khz segments", &LocalizationScanConfig::frequency_khz,
               &LocalizationScanConfig::segments);
  config_class(m, "CorrelationConfig", "chain realizations max_distance", &C::chain, &C::realizations, &C::max_distance);
  using B = ButterflyConfig;
  config_class(m, "ButterflyConfig", "chain ratios realization largest_box smallest_box_spacings box_sizes", &B::chain,
               &B::ratios, &B::realization, &B::largest_box, &B::smallest_box_spacings, &B::box_sizes);
  m.def("_ipr_map", &ipr_map);
  m.def("_localization", &localization);
  m.def("_validate_localization", py::overload_cast<const LocalizationScanConfig&>(&validate));  // f, segments
  m.def("_localization_chain", &localization_chain);  // the chain keywords' defaults
  // granular.ipr_map's and granular.correlations' chain keywords' defaults: their studies' default chain
  m.def("_ipr_map_chain", &ipr_map_chain_defaults);
  m.attr("_ipr_map_defaults") = text_defaults(ipr_map_parameters());  // xi, q as the tool's --help shows them
  m.def("_correlation_chain", &correlation_chain_defaults);
  m.attr("_localization_frequencies") = localization_frequencies;
  m.def("_correlations", &correlations);
  m.def("_butterfly", &butterfly);
  m.attr("_butterfly_defaults") = text_defaults(butterfly_parameters());  // ratios as the tool's --help shows them
  using D = DynamicalButterflyConfig;  // the table's parameters; the chain, ratios, realization: granular/_studies.py
  table_class(m, "DynamicalButterflyConfig", dynamical_butterfly_parameters())
      .def_readwrite("chain", &D::chain)
      .def_readwrite("ratios", &D::ratios)
      .def_readwrite("realization", &D::realization);
  m.def("_dynamical_butterfly", &dynamical_butterfly);
}

}  // namespace granular::python
