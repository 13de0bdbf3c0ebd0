// The nonlinear dynamics under granular.spreading, granular.transport and granular.exponent_table,
// whose keywords, defaults and docstrings live in granular/_dynamics.py. Here: the library's
// structs (TransportCase with its ModeKick, its parameters' attributes made from transport_parameters() and
// spreading_output_parameters(), ChainRecipe, ExponentChoices, ExponentTableConfig) bound with their C++
// defaults, and one call per job that takes them, completes the case by the tools' rules
// (case/transport_parameters.hpp, exponent_choices.hpp), runs it and returns the library's result
// (granular/_dynamics.py shapes it) or the tool's CSV text, with the library's own JSON.
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "bindings.hpp"
#include "granular/case/case_settling.hpp"
#include "granular/case/kicked_case.hpp"
#include "granular/case/spreading_outputs.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/files/exponent_files.hpp"
#include "granular/files/spreading_files.hpp"
#include "granular/model/quasiperiodic.hpp"
#include "granular/study/exponent_choices.hpp"
#include "granular/study/exponent_table.hpp"
#include "granular/study/frequency_slips.hpp"
#include "granular/study/paper_comparison.hpp"

namespace granular::python {
namespace {

py::object csv_text(const std::function<void(std::ostream&)>& write) {
  std::ostringstream out;
  write(out);
  return py::str(out.str());
}

/// `c`: the case as granular/_dynamics.py fills it (its parameters, outputs, kick, mode), one
/// realization of `chain`.
py::dict spreading(const PyChain& chain, TransportCase c, const PyRun& options) {
  c.chain = chain.recipe;
  SpreadingRunConfig& d = c.dynamics;
  fit_within_duration(c);                                  // a window beyond T: no exponents
  refuse_mode_without_mode_kick(c.mode, {c.kick});         // only a mode kick takes mode, near_khz, energy
  warn(frequency_slips(c.mode, c.chain, front_end_word));  // near_khz: Hz typed as kHz
  // τ by the stability rule on the chain's recipe: every realization of a random chain (as the
  // tool's --disorder), this very chain for a given one (as the tool's --config/--radii); a dt past
  // it named before anything judged on its grid.
  std::string t_warning;
  const nlohmann::json step_rule = validate_and_settle(c, "T", t_warning);
  if (!t_warning.empty()) warn({t_warning});  // after the errors
  const KickedChain kicked = kick(c, chain.chain);

  SpreadingResult r;
  std::optional<TransportExponents> exponents;
  run_long("spreading", 1, options, [&](const RunOptions& run) {
    r = run_spreading(chain.chain, kicked.initial, spreading_config(c));
    if (c.fit) exponents = transport_exponents(c, r.t, r.m2, r.m2_centroid, r.ipr);
    run.progress->advance();
  });

  const nlohmann::json meta =
      describe_spreading({.c = c,
                          .chain = chain.description,
                          .kicked = kicked,
                          .step_rule = step_rule,
                          .exponents = exponents,
                          .run = &r,
                          .realization = chain.description.value("realization", nlohmann::json(0))});
  const nlohmann::json fitted = describe_exponents(exponents, c.centre);

  std::vector<std::string> said = notes(c);
  for (const auto& w : warnings(r, d)) said.push_back(w);
  // granular/_dynamics.py makes the granular.SpreadingRun of the bound result.
  return fields("run exponents warnings metadata", std::move(r), to_python(fitted), warn(said),
                metadata("spreading", meta));
}

/// `chain` and `given`: the case as granular/_dynamics.py fills them, made one case by the tool's rule
/// (kicked_case); `profile`: average E_n(T) over every realization.
py::dict transport(const ChainChoices& chain, const TransportCase& given, bool profile, const PyRun& options) {
  KickedCase k = kicked_case(chain, given, true, radius_names(chain, front_end_word));
  warn(k.warnings);  // implausible radii, before the run as the tool says them
  warn(frequency_slips(k.c.mode, k.c.chain, front_end_word));  // near_khz: Hz typed as kHz
  TransportCase& c = k.c;
  if (profile) c.profile_realizations = c.realizations;
  std::string t_warning;
  const nlohmann::json step_rule = validate_and_settle(c, "T", t_warning);
  if (!t_warning.empty()) warn({t_warning});  // after the errors
  const int thread_request = options.thread_request();
  const std::string& log = options.checkpoint;
  // The chain of realization 0, as the tool describes it (and the β it kicks it with).
  const KickedChain first = kick(c, k.selected.chain);

  // Read before the run, which rewrites the checkpoint under this code's name.
  const nlohmann::json resumed = resumed_code(options, {log});
  TransportSummary s;
  run_long("transport", c.realizations, options, [&](const RunOptions& run) { s = run_transport_study(c, run); });
  if (!log.empty()) CheckpointLog::remove_all(log);  // finished: the result is in memory, as the tool's in files

  const nlohmann::json meta = describe_spreading({.c = c,
                                                  .chain = k.selected.description,
                                                  .kicked = first,
                                                  .step_rule = step_rule,
                                                  .exponents = s.exponents,
                                                  .ensemble = &s,
                                                  .threads = thread_request,
                                                  .resumed = resumed});
  const nlohmann::json fitted = describe_exponents(s.exponents, c.centre);

  std::vector<std::string> said = notes(c);
  for (const auto& w : warnings(s, c.dynamics)) said.push_back(w);
  said.push_back(excluded_note(c, s));  // "" (no warning) unless skip_failed left realizations out
  // granular/_dynamics.py makes the granular.Transport of the bound summary.
  return fields("summary exponents warnings metadata", std::move(s), to_python(fitted), warn(said),
                metadata("transport", meta));
}

/// `words`: the chains as granular/_dynamics.py fills them (the tool's rule makes config's of them);
/// config: the kinds, kicks, F0s and profiles; config.base: the dynamics keywords and the mode.
py::dict exponent_table(const ExponentChoices& words, ExponentTableConfig config, const std::string& paper_path,
                        const PyRun& options) {
  set_chains(words, config);
  TransportCase& base = config.base;
  auto cases = exponent_cases(config);
  std::string t_warning;  // one is enough: the cases share T
  const nlohmann::json step_rule = validate_and_settle(cases, "T", t_warning);
  if (!t_warning.empty()) warn({t_warning});     // after the errors
  warn(frequency_slips(cases, front_end_word));  // near_khz: Hz typed as kHz, as the tool warns
  base.dynamics = cases.front().dynamics;        // τ and scheme as settled
  const int thread_request = options.thread_request();
  const std::string& prefix = options.checkpoint;
  const bool compare = !paper_path.empty();  // "": no comparison with the paper's Table I
  const std::vector<PaperCell> paper = compare ? read_paper_table(paper_path) : std::vector<PaperCell>{};

  const nlohmann::json resumed = resumed_code(options, case_checkpoints(prefix, cases.size()));  // before the run
  std::vector<ExponentCell> cells;
  run_long("exponent_table", total_realizations(cases), options,
           [&](const RunOptions& o) { cells = run_exponent_table(config, cases, o); });
  if (!prefix.empty())
    for (const std::string& log : case_checkpoints(prefix, cells.size())) CheckpointLog::remove_all(log);

  for (const ExponentCell& c : cells) warn({excluded_note(c.definition, c.summary)});  // "" when none
  nlohmann::json meta = describe_exponent_study(config, thread_request, cells, step_rule, resumed);
  py::dict out;
  // The tool's three CSV files, written by the library's own writers (granular._results reads them).
  out["table_csv"] = csv_text([&](std::ostream& o) { write_exponents_csv(o, cells); });
  out["curves_csv"] = csv_text([&](std::ostream& o) { write_curves_csv(o, cells); });
  out["profiles_csv"] = csv_text([&](std::ostream& o) { write_profiles_csv(o, cells); });
  out["markdown"] = markdown_tables(cells, config);
  if (compare) {
    const auto rows = compare_with_paper(cells, paper);
    out["paper_csv"] = csv_text([&](std::ostream& o) { write_comparison_csv(o, rows); });
    out["paper_markdown"] = markdown_comparison(rows);
    meta["paper_table"] = paper_path;
  }
  out["metadata"] = metadata("exponent_table", meta);
  return out;
}

}  // namespace

void bind_dynamics(py::module_& m) {
  m.attr("paper_beta") = paper_beta;
  m.attr("_preferred_time_step") = IntegrationConfig{}.time_step;  // granular.spread's dt, the paper's 1 us
  m.attr("_paper_table") = GRANULAR_SOURCE_DIR "/data/paper_table1_gamma.csv";  // compare_paper=True
  table_class(m, "ModeKick", mode_kick_parameters());
  using R = ChainRecipe;
  // The source (a sum type in C++) as granular/_model.py fills it: setting `quasi`, `given_radii` or
  // `given_types` chooses that source; `disorder`, `q` and `xi` set the two-type draw's (ξ: given types' too).
  config_class(m, "ChainRecipe", "R1 N F0 material seed", &R::R1, &R::N, &R::F0, &R::material, &R::seed)
      .def_property(
          "disorder", [](const R& r) { return to_string(r.draw().disorder); },
          [](R& r, const std::string& name) { r.draw().disorder = disorder_of(name); })
      .def_property(
          "q", [](const R& r) { return r.draw().q; }, [](R& r, double q) { r.draw().q = q; })
      .def_property(
          "xi", [](const R& r) { return r.xi(); },
          [](R& r, double xi) {
            if (auto* given = r.as<GivenTypes>()) given->xi = xi;
            else r.draw().xi = xi;
          })
      .def_property(
          "quasi",
          [](const R& r) { return r.as<Quasiperiodic>() ? std::optional(*r.as<Quasiperiodic>()) : std::nullopt; },
          [](R& r, const std::optional<Quasiperiodic>& q) {
            r.source = q ? ChainSource(*q) : ChainSource(TwoTypeDraw{});
          })
      .def_property(
          "given_radii",
          [](const R& r) { return r.as<GivenRadii>() ? std::optional(r.as<GivenRadii>()->radii) : std::nullopt; },
          [](R& r, const std::vector<double>& radii) { r.source = GivenRadii{.radii = radii}; })
      .def_property(
          "given_types",
          [](const R& r) { return r.as<GivenTypes>() ? std::optional(r.as<GivenTypes>()->types) : std::nullopt; },
          [](R& r, const Configuration& types) { r.source = GivenTypes{.types = types, .xi = r.xi()}; })
      .def_property(
          "walls", [](const R& r) { return r.walls == WallShape::flat ? "flat" : "sphere"; },
          [](R& r, const std::string& word) { r.walls = parse_wall_shape(word); })
      .def("_validate_quasi", [](const R& r) { validate(std::get<Quasiperiodic>(r.source), r.F0); });
  using C = TransportCase;                    // an attribute per parameter row, and what the keywords give beyond them
  static const ParameterTable<C> rows = [] {  // the run's, then granular.spreading's outputs
    ParameterTable<C> all = transport_parameters();
    const ParameterTable<C>& outputs = spreading_output_parameters();
    all.insert(all.end(), outputs.begin(), outputs.end());
    return all;
  }();
  py::list outputs;
  for (const Parameter<C>& p : spreading_output_parameters()) outputs.append(p.name);
  m.attr("_spreading_output_parameters") = outputs;
  table_class(m, "TransportCase", rows)
      .def_readwrite("chain", &C::chain)
      .def_readwrite("realizations", &C::realizations)
      .def_readwrite("profile_realizations", &C::profile_realizations)
      .def_readwrite("mode", &C::mode)
      .def_property("kick", word_getter(&C::kick), word_setter(&C::kick, parse_kick));
  using E = ExponentTableConfig;
  config_class(m, "ExponentTableConfig", "precompressions profile_precompressions profile_realizations base",
               &E::precompressions, &E::profile_precompressions, &E::profile_realizations, &E::base)
      .def_property(  // the kinds in words, as the table's `chains` row reads them ("none" alone: no kind)
          "chains",
          [](const E& e) {
            std::vector<std::string> words;
            for (Disorder d : e.chains) words.push_back(to_string(d));
            return words;
          },
          [](E& e, const std::vector<std::string>& words) { e.chains = parse_chain_kinds(words); })
      .def_property(
          "ic",
          [](const E& e) {
            std::vector<std::string> words;
            for (Kick k : e.kicks) words.push_back(to_string(k));
            return words;
          },
          [](E& e, const std::vector<std::string>& words) { e.kicks = parse_kicks(words); });
  using W = ExponentChoices;  // the chain of one's own in words; beads: every chain's choices
  table_class(m, "ExponentChoices", exponent_parameters()).def_readwrite("beads", &W::beads);
  table_class(m, "ChainChoices", chain_parameters());
  // The quasiperiodic chain of the choices (None without `quasi`) by the tools' rule: a keyword
  // that takes no effect on it (angle with s1) is refused.
  m.def("_quasiperiodic", [](const ChainChoices& c) { return quasiperiodic(c); });
  m.def("_kicked_chain_defaults", &kicked_chain_defaults);  // granular.transport's chain keywords' defaults
  table_class(m, "_RunOptions", long_run_parameters());     // the library's rows
  py::class_<PyRun, RunOptions>(m, "RunOptions")
      .def(py::init<>())
      .def_readwrite("checkpoint", &PyRun::checkpoint)
      .def_readwrite("progress", &PyRun::progress_bar);
  // What granular/_dynamics.py makes a SpreadingRun and a Transport of (copies of the arrays).
  readonly(py::class_<LyapunovSeries>(m, "_LyapunovSeries"), "time exponents gali sali", &LyapunovSeries::time,
           &LyapunovSeries::exponents, &LyapunovSeries::gali, &LyapunovSeries::sali);
  using Clv = CovariantVectors;  // the vectors as PREFIX-clv.h5 holds them (covariant_rows)
  readonly(py::class_<Clv>(m, "_CovariantVectors"), "time growth_rates exponents split_angles participation centre",
           &Clv::time, &Clv::growth_rates, &Clv::exponents, &Clv::split_angles, &Clv::participation, &Clv::centre)
      .def_property_readonly("rows", [](const Clv& c) { return to_py(covariant_rows(c)); });
  using Run = SpreadingResult;
  readonly(py::class_<Run>(m, "_SpreadingResult"),
           "t m2 m2_centroid ipr energy_error dissipated mle deviation_t deviation lyapunov covariant initial_energy "
           "max_energy_error "
           "final_state final_energy final_force force_t forces map_t map_energy map_columns spectrum_khz spectrum "
           "wall_energy reached_walls energy_guard_time steps seconds",
           &Run::t, &Run::m2, &Run::m2_centroid, &Run::ipr, &Run::energy_error, &Run::dissipated, &Run::mle,
           &Run::deviation_t, &Run::deviation, &Run::lyapunov, &Run::covariant, &Run::initial_energy,
           &Run::max_energy_error, &Run::final_state, &Run::final_energy, &Run::final_force, &Run::force_t,
           &Run::forces, &Run::map_t, &Run::map_energy, &Run::map_columns, &Run::spectrum_khz, &Run::spectrum,
           &Run::wall_energy, &Run::reached_walls, &Run::energy_guard_time, &Run::steps, &Run::seconds);
  readonly(py::class_<SeriesSummary>(m, "_SeriesSummary"), "mean standard_error", &SeriesSummary::mean,
           &SeriesSummary::standard_error);
  using Sum = TransportSummary;
  readonly(py::class_<Sum>(m, "_TransportSummary"),
           "t m2 m2_centroid ipr energy_error profile mle max_energy_error reached_walls realizations", &Sum::t,
           &Sum::m2, &Sum::m2_centroid, &Sum::ipr, &Sum::energy_error, &Sum::profile, &Sum::mle, &Sum::max_energy_error,
           &Sum::reached_walls, &Sum::realizations);
  m.def("_spreading", &spreading);
  m.def("_transport", &transport);
  m.def("_exponent_table", &exponent_table);
}

}  // namespace granular::python
