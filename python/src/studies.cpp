// The linear studies: granular.ipr_map (the paper's IPR map) and granular.correlations (the
// ensemble of bead-type correlations). Both run long: the GIL is released, threads= spreads the
// chains over cores (results do not depend on it), progress=True draws a bar, Ctrl-C stops them.
#include <nlohmann/json.hpp>
#include <string>

#include "bindings.hpp"
#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/error.hpp"
#include "granular/model/bead_source.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/model/plausibility.hpp"
#include "granular/number_format.hpp"
#include "granular/study/correlation_files.hpp"
#include "granular/study/ipr_map_files.hpp"
#include "granular/study/localization_files.hpp"

namespace granular::python {
namespace {

struct PyIprMap {
  IprMapConfig config;
  std::vector<IprMapCell> cells;
  nlohmann::json metadata;
  bool selection() const { return config.selection.kind != ModeSelection::Kind::all; }
};

/// Every mode: Q × X × N of one field of the cells; with a selection: the rows, concatenated.
py::array_t<double> gather(const PyIprMap& map, std::vector<double> IprMapCell::*field) {
  std::vector<double> out;
  for (const auto& cell : map.cells) out.insert(out.end(), (cell.*field).begin(), (cell.*field).end());
  if (map.selection()) return to_numpy(std::move(out));
  const std::size_t q = map.config.q_values.size(), x = map.config.xi_values.size(), n = map.config.chain.N;
  auto* owner = new std::vector<double>(std::move(out));
  py::capsule base(owner, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>({q, x, n}, {x * n * sizeof(double), n * sizeof(double), sizeof(double)}, owner->data(),
                             base);
}

py::dict ipr_map_rows(const PyIprMap& map) {
  if (map.config.bin_khz > 0 && !map.selection()) {  // frequency bins: the tool's binned CSV
    std::vector<double> q, xi, lo, hi, ipr;
    std::vector<long long> modes;
    const double w = map.config.bin_khz;
    for (const auto& cell : map.cells)
      for (std::size_t b = 0; b < cell.bin_modes.size(); ++b) {
        q.push_back(cell.q);
        xi.push_back(cell.xi);
        lo.push_back(static_cast<double>(b) * w);
        hi.push_back(static_cast<double>(b + 1) * w);
        modes.push_back(static_cast<long long>(cell.bin_modes[b]));
        ipr.push_back(cell.bin_ipr[b]);
      }
    py::dict d;
    d["q"] = to_numpy(std::move(q));
    d["xi"] = to_numpy(std::move(xi));
    d["freq_lo_khz"] = to_numpy(std::move(lo));
    d["freq_hi_khz"] = to_numpy(std::move(hi));
    d["modes"] = to_numpy(std::move(modes));
    d["ipr"] = to_numpy(std::move(ipr));
    return d;
  }
  std::vector<double> q, xi, freq, ipr;
  std::vector<long long> mode, realization;
  for (const auto& cell : map.cells) {
    const std::size_t rows = cell.freq_khz.size();
    for (std::size_t j = 0; j < rows; ++j) {
      q.push_back(cell.q);
      xi.push_back(cell.xi);
      mode.push_back(map.selection() ? static_cast<long long>(cell.mode[j]) : static_cast<long long>(j + 1));
      if (map.selection()) realization.push_back(static_cast<long long>(cell.realization[j]));
      freq.push_back(cell.freq_khz[j]);
      ipr.push_back(cell.ipr[j]);
    }
  }
  py::dict d;
  d["q"] = to_numpy(std::move(q));
  d["xi"] = to_numpy(std::move(xi));
  if (map.selection()) d["realization"] = to_numpy(std::move(realization));
  d["mode"] = to_numpy(std::move(mode));
  d["freq_khz"] = to_numpy(std::move(freq));
  d["ipr"] = to_numpy(std::move(ipr));
  return d;
}

struct PyCorrelations {
  CorrelationResult result;
  nlohmann::json metadata;
};

int thread_count(long long threads) { return static_cast<int>(checked_size(threads, "threads", 0, 4096)); }

struct PyLocalization {
  LocalizationScan scan;
  nlohmann::json metadata;
};

/// The beads of a Chain argument, as the localization tool reads a --config (types) or --radii
/// (radii) file; or a random realization drawn on demand (memory independent of N).
struct Beads {
  std::unique_ptr<BeadSource> source;
  nlohmann::json description;
};
Beads beads_of(const PyChain& c) {
  Beads b;
  b.description = c.description;
  if (!(c.chain.precompression > 0)) bad_value("F0", " 0: the sonic vacuum has no linear limit (needs F0 > 0)");
  if (!c.types.empty() && c.description.contains("xi")) {
    ChainParameters p;
    p.xi = c.description["xi"].get<double>();
    p.R1 = c.description["R1_m"].get<double>();
    p.F0 = c.chain.precompression;
    p.material = c.material;
    b.source = typed_beads(c.types, p);
  } else {
    b.source = chain_beads(c.chain);
  }
  return b;
}

}  // namespace

void bind_studies(py::module_& m) {
  py::class_<PyIprMap>(m, "IprMap",
                       "The result of granular.ipr_map. Every mode: freq_khz and ipr are (len(q), len(xi), N) arrays "
                       "of means over the realizations (mode k at index k-1). With near/count or window: one entry "
                       "per selected mode of every realization (see rows()).")
      .def_property_readonly(
          "disorder", [](const PyIprMap& p) { return to_string(p.config.chain.disorder); }, "h | A | RDM1 | RDM2")
      .def_property_readonly(
          "q", [](const PyIprMap& p) { return to_numpy(p.config.q_values); }, "the q grid")
      .def_property_readonly(
          "xi", [](const PyIprMap& p) { return to_numpy(p.config.xi_values); }, "the xi grid (R2/R1)")
      .def_property_readonly(
          "N", [](const PyIprMap& p) { return p.config.chain.N; }, "beads per chain")
      .def_property_readonly("selection", &PyIprMap::selection, "True when made with near/count or window")
      .def_property_readonly(
          "freq_khz", [](const PyIprMap& p) { return gather(p, &IprMapCell::freq_khz); },
          "mean mode frequencies [kHz], (len(q), len(xi), N); with a selection, one per row")
      .def_property_readonly(
          "ipr", [](const PyIprMap& p) { return gather(p, &IprMapCell::ipr); },
          "mean displacement IPRs, (len(q), len(xi), N); with a selection, one per row")
      .def_property_readonly(
          "bin_khz", [](const PyIprMap& p) { return p.config.bin_khz; },
          "width of the frequency bins [kHz] (0: averaged by mode number)")
      .def("rows", &ipr_map_rows,
           "The ipr-map tool's CSV columns as arrays: q, xi, [realization,] mode, freq_khz [kHz], ipr (one row per "
           "(q, xi, mode), or per selected mode of each realization); with bin_khz > 0: q, xi, freq_lo_khz, "
           "freq_hi_khz, modes (of all realizations in the bin), ipr (their mean; NaN for an empty bin)")
      .def_property_readonly(
          "metadata", [](const PyIprMap& p) { return to_python(p.metadata); },
          "the ipr-map tool's JSON: parameters (disorder, xi, q, N, F0_N, R1_m, material, "
          "walls, realizations, seed, threads, solver), averaging and bin_khz or selection, clustered, version "
          "(granular::describe_ipr_map, as the tool writes it)")
      .def("__repr__", [](const PyIprMap& p) {
        return "<granular.IprMap " + to_string(p.config.chain.disorder) + ", " +
               std::to_string(p.config.q_values.size()) + " q x " + std::to_string(p.config.xi_values.size()) +
               " xi, N=" + std::to_string(p.config.chain.N) + ">";
      });

  m.def(
      "ipr_map",
      [](const std::string& disorder, const py::object& xi, const py::object& q, long long N, double F0, double R1,
         long long realizations, long long seed, const std::string& solver, const py::object& near,
         const py::object& count, const py::object& window, const py::object& method, double bin_khz, long long threads,
         bool progress) {
        PyIprMap map;
        IprMapConfig& c = map.config;
        c.chain.disorder = disorder_of(disorder);
        c.xi_values = number_list(xi, "xi", 0.01);
        c.q_values = number_list(q, "q", 0.1);
        c.chain.N = checked_size(N, "N", 2, 100000000);
        c.chain.F0 = F0;
        c.chain.R1 = R1;
        c.realizations = checked_size(realizations, "realizations", 1);
        c.chain.seed = checked_size(seed, "seed");
        const int thread_request = thread_count(threads);
        if (solver != "fast" && solver != "lapack" && !solver.starts_with("lapack-"))
          bad_value("solver", " '" + solver + "': expected fast, lapack or lapack-<stevr|stemr|stevd|steqr>");
        c.spectrum.method = solver == "fast" ? SpectrumMethod::fast : SpectrumMethod::lapack;
        if (solver.starts_with("lapack-")) {
          try {
            c.spectrum.driver = parse_lapack_driver(solver.substr(7));
          } catch (const InvalidInput&) {
            bad_value("solver", " '" + solver + "': expected fast, lapack or lapack-<stevr|stemr|stevd|steqr>");
          }
        }
        const bool selected = !near.is_none() || !count.is_none() || !window.is_none();
        std::string method_name = method.is_none() ? "lapack" : method.cast<std::string>();
        if (selected) {
          if (!window.is_none()) {
            if (!near.is_none() || !count.is_none()) bad_value("window", ": cannot be combined with near/count");
            const std::vector<double> w = double_vector(window, "window", false);
            if (w.size() != 2) bad_value("window", ": expected (lo, hi) in kHz");
            c.selection = granular::window(w[0], w[1]);
          } else {
            if (count.is_none()) bad_value("near", ": needs count (how many modes)");
            if (near.is_none()) bad_value("count", ": needs near (the target frequency in kHz)");
            const long long k = count.cast<long long>();
            if (k < 1) bad_value("count", " " + std::to_string(k) + ": must be >= 1");
            c.selection = nearest(near.cast<double>(), static_cast<long>(std::min<long long>(k, 1LL << 40)));
          }
          c.spectrum.method = parse_spectrum_method(method_name);
          if (c.spectrum.method == SpectrumMethod::fast)
            bad_value("method", " fast: computes every mode; use lapack, bisect or arpack with near/window");
        } else if (!method.is_none()) {
          bad_value("method", ": only with near/count or window (the full map uses solver=)");
        }
        c.bin_khz = bin_khz;
        validate(c);

        run_long("ipr_map", c.q_values.size() * c.xi_values.size() * c.realizations, progress,
                 [&](const LongRun& control) {
                   RunOptions run;
                   run.threads = thread_request;
                   run.progress = control.meter;
                   run.cancelled = control.cancelled;
                   map.cells = compute_ipr_map(c, run);
                 });

        nlohmann::json meta = metadata_head("ipr_map");
        meta.update(describe_ipr_map(c, map.cells, {solver, method_name, resolve_threads(thread_request)}));
        map.metadata = std::move(meta);
        return map;
      },
      py::kw_only(), py::arg("disorder") = "A", py::arg("xi") = "0.1:1", py::arg("q") = "0.2,0.5,0.8",
      py::arg("N") = 100, py::arg("F0") = 10.0, py::arg("R1") = paper_r1, py::arg("realizations") = 100,
      py::arg("seed") = 1, py::arg("solver") = "fast", py::arg("near") = py::none(), py::arg("count") = py::none(),
      py::arg("window") = py::none(), py::arg("method") = py::none(), py::arg("bin_khz") = 0.0, py::arg("threads") = 0,
      py::arg("progress") = false,
      "Mean frequency [kHz] and displacement IPR of every mode of disordered chains over realizations, on a (q, xi) "
      "grid: the paper's IPR map, as the ipr-map tool computes it (same numbers for the same keywords).\n\n"
      "    disorder: 'h' | 'A' | 'RDM1' | 'RDM2'\n"
      "    xi, q: size ratios R2/R1 in (0, 1] and probabilities in [0, 1]: sequences, numbers, or the tools' range "
      "strings ('0.1:1' = 0.1, 0.11, ..., 1; '0.1:1:0.05'; '0.2,0.5,0.8')\n"
      "    N: beads per chain; F0: precompression [N] (> 0); R1: type-1 radius [m]\n"
      "    realizations, seed: chains averaged per cell; realization r of seed s is always the same chain, and all "
      "xi of one q share the bead sequences\n"
      "    solver: 'fast' (default) | 'lapack' | 'lapack-stevr' | 'lapack-stemr' | 'lapack-stevd' | 'lapack-steqr'\n"
      "    near, count / window: partial spectra (every selected mode of every realization, not averaged) by "
      "method = 'lapack' | 'bisect' | 'arpack'\n"
      "    bin_khz: W > 0 averages every mode in frequency bins [k W, (k+1) W) [kHz] instead of by mode number "
      "(see IprMap.rows())\n"
      "    threads: worker threads (0: every core); the result does not depend on it\n"
      "    progress: draw a progress bar on stderr\n"
      "Returns a granular.IprMap. Releases the GIL; Ctrl-C stops it (KeyboardInterrupt) after the cell in flight.");

  py::class_<PyLocalization>(m, "Localization",
                             "The result of granular.localization: per frequency the transfer-matrix Lyapunov "
                             "exponent, the localization length and the density of states (the localization tool's "
                             "columns).")
      .def_property_readonly(
          "freq_khz", [](const PyLocalization& p) { return to_numpy(p.scan.frequency_khz); }, "frequencies f [kHz]")
      .def_property_readonly(
          "lyapunov", [](const PyLocalization& p) { return to_numpy(p.scan.lyapunov); },
          "lambda = (1/N) ln ||(u_(N+1), u_N)|| [1/bead]: the inverse localization length")
      .def_property_readonly(
          "lyapunov_err", [](const PyLocalization& p) { return to_numpy(p.scan.lyapunov_error); },
          "standard error of lambda from the chain's segments [1/bead]")
      .def_property_readonly(
          "loc_length", [](const PyLocalization& p) { return to_numpy(p.scan.localization_length); },
          "localization length 1/lambda [beads]; inf where lambda <= 0 (inside a band)")
      .def_property_readonly(
          "resolved",
          [](const PyLocalization& p) {
            py::array_t<bool> flags(static_cast<py::ssize_t>(p.scan.resolved.size()));
            auto view = flags.mutable_unchecked<1>();
            for (std::size_t k = 0; k < p.scan.resolved.size(); ++k)
              view(static_cast<py::ssize_t>(k)) = p.scan.resolved[k] != 0;
            return flags;
          },
          "True where loc_length is a measurement, False where it is only a bound of order N (the rule: "
          "metadata['resolved_rule'])")
      .def_property_readonly(
          "modes_below",
          [](const PyLocalization& p) {
            return to_numpy(std::vector<long long>(p.scan.modes_below.begin(), p.scan.modes_below.end()));
          },
          "eigenfrequencies of the finite chain below f (exact node counts)")
      .def_property_readonly(
          "idos", [](const PyLocalization& p) { return to_numpy(p.scan.idos); },
          "integrated density of states: modes below f per bead")
      .def_property_readonly(
          "dos", [](const PyLocalization& p) { return to_numpy(p.scan.dos); },
          "density of states d idos / df [1/(bead kHz)] (one frequency: from counts at f -/+ 0.005 kHz)")
      .def_property_readonly(
          "N", [](const PyLocalization& p) { return p.scan.beads; }, "beads of the chain")
      .def_property_readonly(
          "metadata", [](const PyLocalization& p) { return to_python(p.metadata); },
          "the localization tool's JSON: chain, parameters, columns, band_edges_khz, version "
          "(granular::describe_localization, as the tool writes it)");

  m.def(
      "localization",
      [](const py::object& chain, const std::string& disorder, const py::object& N, double q, double xi, long long seed,
         long long realization, double F0, double R1, const py::object& f, long long segments, long long threads,
         bool progress) {
        LocalizationScanConfig config;
        config.frequency_khz = number_list(f, "f", 0.01);
        for (std::size_t k = 0; k < config.frequency_khz.size(); ++k) {
          const double v = config.frequency_khz[k];
          if (v < 0) bad_value("f", ": frequency " + format_number(v) + " kHz is negative");
          if (k > 0 && !(v > config.frequency_khz[k - 1]))
            bad_value("f", ": frequencies must increase (the DOS differences neighbours)");
        }
        config.segments = checked_size(segments, "segments", 2, 1000000);
        const int thread_request = thread_count(threads);
        Beads beads;
        double top_khz = 0;  // bound on the chain's frequencies, for the unit-slip warning
        if (!chain.is_none()) {
          if (!py::isinstance<PyChain>(chain)) throw py::type_error("chain: expected a granular.Chain or None");
          beads = beads_of(chain.cast<const PyChain&>());
          top_khz = highest_frequency_bound_khz(chain.cast<const PyChain&>().recipe);
        } else {
          const double n = N.cast<double>();
          if (!(n >= 2) || !(n <= 1e12) || n != std::floor(n))
            bad_value("N", " " + format_number(n) + ": must be a whole number of beads in [2, 1e12]");
          const Disorder kind = disorder_of(disorder);
          const ChainParameters p{.N = static_cast<std::size_t>(n),
                                  .q = q,
                                  .xi = xi,
                                  .seed = checked_size(seed, "seed"),
                                  .realization = checked_size(realization, "realization"),
                                  .F0 = F0,
                                  .R1 = R1};
          beads.source = random_beads(kind, p);
          ChainRecipe recipe{.disorder = kind, .q = q, .xi = xi, .R1 = R1, .F0 = F0};
          warn(radius_warnings(recipe, {"R1", "beads", "radii"}));
          top_khz = highest_frequency_bound_khz(recipe);
          beads.description = {{"F0_N", F0},
                               {"material", describe(steel)},
                               {"walls", flat_walls_description},
                               {"R1_m", R1},
                               {"xi", xi},
                               {"disorder", to_string(kind)},
                               {"q", q},
                               {"seed", seed},
                               {"realization", realization}};
        }
        beads.description["N"] = beads.source->size();
        validate(config);
        for (double v : config.frequency_khz)  // the first one above the chain's frequencies
          if (const std::string w = frequency_warning("f", v, top_khz); !w.empty()) {
            warn({w});
            break;
          }
        PyLocalization out;
        run_long("localization", beads.source->size() * config.frequency_khz.size(), progress,
                 [&](const LongRun& control) {
                   RunOptions run;
                   run.threads = thread_request;
                   run.progress = control.meter;
                   run.cancelled = control.cancelled;
                   out.scan = localization_scan(*beads.source, config, run);
                 });
        nlohmann::json meta = metadata_head("localization");
        meta.update(describe_localization(out.scan, beads.description,
                                          py::isinstance<py::str>(f) ? nlohmann::json(f.cast<std::string>())
                                                                     : nlohmann::json(config.frequency_khz),
                                          resolve_threads(thread_request), steel));
        out.metadata = std::move(meta);
        return out;
      },
      py::arg("chain") = py::none(), py::kw_only(), py::arg("disorder") = "A", py::arg("N") = 1000000,
      py::arg("q") = 0.5, py::arg("xi") = 0.5, py::arg("seed") = 1, py::arg("realization") = 0, py::arg("F0") = 10.0,
      py::arg("R1") = paper_r1, py::arg("f") = "0:50:0.01", py::arg("segments") = 32, py::arg("threads") = 0,
      py::arg("progress") = false,
      "Localization length and density of states of one long chain by transfer matrices (SPEC §3, 'Infinite "
      "chains'): the localization tool.\n\n"
      "    chain: a granular.Chain; or None and a random realization (disorder, N, q, xi, seed, realization, F0 [N], "
      "R1 [m]) drawn a piece at a time, so N = 1e8 needs no more memory than N = 100\n"
      "    f: frequencies [kHz], increasing: a sequence or the tools' range string ('0:50:0.01')\n"
      "    segments: chain pieces whose exponents give lyapunov_err (2 ... 1e6)\n"
      "    threads: workers over blocks of frequencies (0: every core); results do not depend on it\n"
      "Returns a granular.Localization (freq_khz, lyapunov [1/bead], lyapunov_err, loc_length [beads], modes_below, "
      "idos, dos, metadata). Releases the GIL; Ctrl-C stops it.");

  py::class_<PyCorrelations>(m, "Correlations",
                             "The result of granular.correlations: rho(d) for d = 0..max_distance over realizations, "
                             "with the infinite-chain formula.")
      .def_property_readonly(
          "distance",
          [](const PyCorrelations& p) {
            std::vector<long long> d(p.result.mean.size());
            for (std::size_t i = 0; i < d.size(); ++i) d[i] = static_cast<long long>(i);
            return to_numpy(std::move(d));
          },
          "d = 0..max_distance [beads]")
      .def_property_readonly(
          "rho_mean", [](const PyCorrelations& p) { return to_numpy(p.result.mean); }, "ensemble mean of rho(d)")
      .def_property_readonly(
          "rho_std", [](const PyCorrelations& p) { return to_numpy(p.result.deviation); },
          "sample standard deviation of rho(d) over the realizations")
      .def_property_readonly(
          "rho_theory", [](const PyCorrelations& p) { return to_numpy(p.result.theory); },
          "infinite-chain rho(d) (NaN where undefined)")
      .def_property_readonly(
          "used", [](const PyCorrelations& p) { return p.result.used; },
          "realizations with both bead types (one-type chains have no rho and are skipped)")
      .def_property_readonly(
          "metadata", [](const PyCorrelations& p) { return to_python(p.metadata); },
          "the correlations tool's JSON: parameters, correlated, realizations_used, version "
          "(granular::describe_correlations, as the tool writes it)");

  m.def(
      "correlations",
      [](const std::string& disorder, double q, long long N, long long realizations, long long seed,
         long long max_distance, long long threads, bool progress) {
        CorrelationConfig c;
        c.chain.disorder = disorder_of(disorder);
        c.chain.q = q;
        c.chain.N = checked_size(N, "N", 2, 100000000);
        c.realizations = checked_size(realizations, "realizations", 1);
        c.chain.seed = checked_size(seed, "seed");
        c.max_distance = checked_size(max_distance, "max_distance");
        const int thread_request = thread_count(threads);
        validate(c);
        PyCorrelations out;
        run_long("correlations", c.realizations, progress, [&](const LongRun& control) {
          RunOptions run;
          run.threads = thread_request;
          run.progress = control.meter;
          run.cancelled = control.cancelled;
          out.result = correlation_study(c, run);
        });
        out.metadata = metadata_head("correlations");
        out.metadata.update(describe_correlations(c, out.result));
        return out;
      },
      py::kw_only(), py::arg("disorder") = "A", py::arg("q") = 0.5, py::arg("N") = 100, py::arg("realizations") = 100,
      py::arg("seed") = 1, py::arg("max_distance") = 10, py::arg("threads") = 0, py::arg("progress") = false,
      "Ensemble mean and spread of the Pearson coefficient rho(d) of bead types (type 1 -> 0, type 2 -> 1) with their "
      "cyclic shift by d, beside the infinite-chain formula: the correlations tool.\n\n"
      "    disorder: 'A' | 'RDM1' | 'RDM2'; q in [0, 1]; N beads; realizations, seed; max_distance < N\n"
      "    threads: worker threads (0: every core); progress: draw a progress bar\n"
      "Returns a granular.Correlations (distance, rho_mean, rho_std, rho_theory, used, metadata).");
}

}  // namespace granular::python
