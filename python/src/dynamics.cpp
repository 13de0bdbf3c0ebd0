// The nonlinear dynamics: one spreading run (granular.spreading), an ensemble of them
// (granular.transport, the spreading tool's --realizations) and the paper's exponent table
// (granular.exponent_table). Kept thin on purpose — keywords to config structs, results to dicts
// of NumPy arrays wrapped by granular._results — because the library's dynamics API is still
// moving (m̃2 centres, bootstrap errors, observers): this file follows it, nothing else needs to.
#include <cmath>
#include <string>

#include "bindings.hpp"
#include "granular/analysis/power_law_fit.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/dynamics/spreading.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/error.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/number_format.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/study/exponent_table.hpp"
#include "granular/study/transport_study.hpp"

namespace granular::python {
namespace {

/// The keywords every dynamics call shares, as the spreading tool's options.
struct DynamicsKeywords {
  double T, dt;
  std::string force_law, integrator, sampling, energy_guard;
  long long samples;
  bool active_window;
  double window_threshold, reference_max_step, max_energy_error;
};

SpreadingConfig spreading_config(const DynamicsKeywords& k) {
  SpreadingConfig c;
  c.force_law = parse_force_law(k.force_law);
  if (k.integrator != "reference") parse_scheme(k.integrator, "integrator");
  c.integrator = k.integrator;
  c.duration = k.T;
  c.time_step = k.dt;
  c.samples = checked_size(k.samples, "samples", 2, 100000000);
  c.sampling = parse_sampling(k.sampling);
  c.window.enabled = k.active_window;
  c.window.threshold = finite(k.window_threshold, "window_threshold");
  if (!(k.reference_max_step >= 0) || !std::isfinite(k.reference_max_step))
    bad_value("reference_max_step", " " + format_number(k.reference_max_step) + ": must be finite and >= 0");
  c.reference.max_step = k.reference_max_step;
  if (!(k.max_energy_error >= 0) || !std::isfinite(k.max_energy_error))
    bad_value("max_energy_error", " " + format_number(k.max_energy_error) + ": must be finite and >= 0");
  if (k.energy_guard != "stop" && k.energy_guard != "warn")
    bad_value("energy_guard", " '" + k.energy_guard + "': stop or warn");
  c.max_energy_error = k.max_energy_error;
  c.stop_on_energy_error = k.energy_guard == "stop";
  return c;
}

/// fit=(start, stop) [s]: checked, and whether it fits inside T (else no exponents, as the tool).
struct FitWindow {
  double begin = 4e-3, end = 1e-2;
  bool possible = false;
};
FitWindow fit_window(const py::object& fit, const SpreadingConfig& c) {
  const std::vector<double> f = double_vector(fit, "fit");
  if (f.size() != 2 || !(f[0] > 0) || !(f[1] > f[0]))
    bad_value("fit", ": expected (start, stop) [s] with 0 < start < stop");
  FitWindow w{f[0], f[1], f[1] <= c.duration * (1 + 1e-12)};
  if (w.possible) {  // a fit that cannot work is bad input, found before the run
    std::vector<double> times;
    for (auto s :
         sample_steps(static_cast<std::uint64_t>(std::llround(c.duration / c.time_step)), c.samples, c.sampling))
      times.push_back(static_cast<double>(s) * c.time_step);
    try {
      windowed_exponent(times, times, w.begin, w.end);
    } catch (const InvalidInput& e) {
      bad_value("fit", ": too few samples in a sub-window (" + std::string(e.what()) + ")");
    }
  }
  return w;
}

py::dict analysis_dict(const PowerLawAnalysis& a) {
  py::dict d;
  d["value"] = a.exponent.value;
  d["error"] = a.exponent.error;
  d["slopes"] = to_numpy(a.exponent.slopes);
  d["power_law"] = a.verdict.power_law;
  d["worst_deviation"] = a.verdict.worst_deviation;
  d["worst_time"] = a.verdict.worst_time;
  return d;
}

/// The kicked bead, 0-based, from the 1-based keyword (None: the centre).
std::size_t kicked_site(const py::object& site, std::size_t beads) {
  if (site.is_none()) return centre_site(beads);
  const long long s = site.cast<long long>();
  if (s < 1 || s > static_cast<long long>(beads))
    bad_value("site", " " + std::to_string(s) + ": outside the chain of " + std::to_string(beads) + " beads (1..N)");
  return static_cast<std::size_t>(s - 1);
}

/// beta = a number [m/s] or "match" (the energy of alpha on this chain).
struct Beta {
  bool match = false;
  double value = 0;
};
Beta beta_of(const py::object& beta) {
  if (py::isinstance<py::str>(beta)) {
    if (beta.cast<std::string>() != "match")
      bad_value("beta", " '" + beta.cast<std::string>() + "': a number [m/s] or 'match'");
    return {true, 0};
  }
  return {false, finite(beta.cast<double>(), "beta")};
}

nlohmann::json dynamics_parameters(const std::string& ic, std::size_t kicked, double alpha, double beta, bool matched,
                                   const DynamicsKeywords& k, const FitWindow& fit, double kappa) {
  return {{"ic", ic},
          {"site", kicked + 1},
          {"alpha_m", ic == "displacement" ? alpha : 0.0},
          {"beta_m_s", beta},
          {"beta_matched", matched},
          {"T_s", k.T},
          {"dt_s", k.dt},
          {"force_law", k.force_law},
          {"integrator", k.integrator},
          {"samples", k.samples},
          {"sampling", k.sampling},
          {"fit_s", {fit.begin, fit.end}},
          {"kappa", kappa},
          {"t_star_s", fit.begin},
          {"active_window", k.active_window ? "on" : "off"},
          {"window_threshold", k.window_threshold},
          {"reference_max_step_s", k.reference_max_step}};
}

py::object wrap_result(const char* type, py::dict values) {
  return py::module_::import("granular._results").attr(type)(values);
}

const char* dynamics_doc =
    "    ic: 'displacement' (u = alpha at the site) | 'velocity' (v = beta at the site)\n"
    "    alpha: displacement kick [m]; beta: velocity kick [m/s] or 'match' (the energy of alpha on the chain)\n"
    "    site: kicked bead, counting from 1 as the tools do (default the centre, (N+1)/2)\n"
    "    T: duration [s], a whole number of dt; dt: time step tau [s]\n"
    "    force_law: 'hertz' | 'fpu' | 'linear'; integrator: 'saba2c' | 'saba2' | 'aba864' | 'srkn14a' | 'reference'\n"
    "    samples, sampling: sample times of m2, P^-1 and the energy error ('log': tau..T, 'uniform': 0..T)\n"
    "    fit: (start, stop) [s] of the fits gamma (m2 ~ t^gamma) and eta (P^-1 ~ t^-eta); kappa: the 'not a power "
    "law' threshold on |L_d - gamma| after start\n"
    "    active_window: integrate only where the wave has arrived (results equal the full chain's); "
    "window_threshold: relative kinetic energy that grows it\n"
    "    reference_max_step: largest step of the reference integrator [s] (0: none)\n"
    "    max_energy_error, energy_guard: relative energy error that stops the run ('stop', NumericalError) or is "
    "only reported ('warn'); 0 = unwatched\n";

}  // namespace

void bind_dynamics(py::module_& m) {
  m.def(
      "spreading",
      [](const PyChain& chain, const std::string& ic, double alpha, const py::object& beta, const py::object& site,
         double T, double dt, const std::string& force_law, const std::string& integrator, long long samples,
         const std::string& sampling, const py::object& fit, double kappa, const py::object& forces_at,
         long long force_samples, bool energy_map, long long map_samples, long long map_stride, bool spectral_density,
         long long spectrum_samples, bool active_window, double window_threshold, double reference_max_step,
         double max_energy_error, const std::string& energy_guard, bool progress) {
        const DynamicsKeywords k{T,
                                 dt,
                                 force_law,
                                 integrator,
                                 sampling,
                                 energy_guard,
                                 samples,
                                 active_window,
                                 window_threshold,
                                 reference_max_step,
                                 max_energy_error};
        SpreadingConfig config = spreading_config(k);
        const std::size_t beads = chain.chain.size();
        if (ic != "displacement" && ic != "velocity")
          bad_value("ic", " '" + ic + "': expected displacement or velocity");
        if (!forces_at.is_none())
          for (double s : double_vector(forces_at, "forces_at")) {
            if (s != std::floor(s) || s < 1 || s > static_cast<double>(beads))
              bad_value("forces_at",
                        " " + format_number(s) + ": outside the chain of " + std::to_string(beads) + " beads (1..N)");
            config.force_sites.push_back(static_cast<std::size_t>(s) - 1);
          }
        config.force_samples = checked_size(force_samples, "force_samples", 1, 100000000);
        config.map_samples = energy_map ? checked_size(map_samples, "map_samples", 2, 100000000) : 0;
        config.map_stride = checked_size(map_stride, "map_stride", 1, 100000000);
        config.spectrum_samples =
            spectral_density ? checked_size(spectrum_samples, "spectrum_samples", 2, 100000000) : 0;
        validate(config, beads);
        PowerLawCriterion criterion;
        criterion.kappa = kappa;
        if (!(kappa > 0) || !std::isfinite(kappa))
          bad_value("kappa", " " + format_number(kappa) + ": must be finite and > 0");
        const FitWindow w = fit_window(fit, config);
        criterion.t_start = w.begin;

        const std::size_t kicked = kicked_site(site, beads);
        const Beta b = beta_of(beta);
        State initial;
        double beta_used = 0;
        if (ic == "displacement") {
          initial = displacement_kick(chain.chain, kicked, alpha);
        } else {
          beta_used = b.match
                          ? matched_velocity(make_force_law(config.force_law, chain.chain), chain.chain, kicked, alpha)
                          : b.value;
          initial = velocity_kick(chain.chain, kicked, beta_used);
        }

        SpreadingResult r;
        run_long("spreading", 1, progress, [&](const LongRun& control) {
          r = run_spreading(chain.chain, initial, config);
          control.meter->advance();
        });

        py::dict out;
        nlohmann::json meta = metadata_head("spreading");
        meta["parameters"] = dynamics_parameters(ic, kicked, alpha, beta_used, ic == "velocity" && b.match, k, w, kappa);
        meta["parameters"]["chain"] = chain.description;
        meta["parameters"]["realizations"] = 1;
        meta["seed"] = chain.description.contains("seed") ? chain.description["seed"] : nlohmann::json(nullptr);
        for (const char* key : {"gamma", "gamma_err", "eta", "eta_err", "power_law"}) meta[key] = nullptr;
        out["gamma"] = py::none();
        out["eta"] = py::none();
        if (w.possible) {
          const PowerLawAnalysis g = analyze_power_law(r.t, r.m2, w.begin, w.end, criterion);
          std::vector<double> inverse_ipr;
          for (double p : r.ipr) inverse_ipr.push_back(1 / p);  // P⁻¹ ∝ t^−η  ⇔  1/P⁻¹ ∝ t^η
          const ExponentEstimate e = windowed_exponent(r.t, inverse_ipr, w.begin, w.end);
          meta["gamma"] = g.exponent.value, meta["gamma_err"] = g.exponent.error;
          meta["eta"] = e.value, meta["eta_err"] = e.error;
          meta["power_law"] = g.verdict.power_law;
          meta["max_log_derivative_deviation"] = g.verdict.worst_deviation;
          out["gamma"] = analysis_dict(g);
          py::dict eta;
          eta["value"] = e.value, eta["error"] = e.error, eta["slopes"] = to_numpy(e.slopes);
          out["eta"] = eta;
        }
        meta["run"] = {{"realization", chain.description.value("realization", nlohmann::json(nullptr))},
                       {"initial_energy_J", r.initial_energy},
                       {"max_energy_error", r.max_energy_error},
                       {"steps", r.steps},
                       {"bond_updates", r.bond_updates},
                       {"integration_s", r.seconds},
                       {"window_final", {r.window_begin + 1, r.window_end}},
                       {"wall_energy", r.wall_energy},
                       {"reached_walls", r.reached_walls}};

        out["t"] = to_numpy(std::move(r.t));
        out["m2"] = to_numpy(std::move(r.m2));
        out["ipr"] = to_numpy(std::move(r.ipr));
        out["energy_error"] = to_numpy(std::move(r.energy_error));
        out["initial_energy"] = r.initial_energy;
        out["max_energy_error"] = r.max_energy_error;
        py::dict final_state;
        final_state["u"] = to_numpy(std::move(r.final_state.u));
        final_state["v"] = to_numpy(std::move(r.final_state.v));
        final_state["energy"] = to_numpy(std::move(r.final_energy));
        final_state["force"] = to_numpy(std::move(r.final_force));
        out["final_state"] = final_state;
        out["forces"] = py::none();
        if (!config.force_sites.empty()) {
          py::dict f;
          std::vector<long long> sites;
          std::vector<double> values;
          for (std::size_t j = 0; j < config.force_sites.size(); ++j) {
            sites.push_back(static_cast<long long>(config.force_sites[j] + 1));
            values.insert(values.end(), r.forces[j].begin(), r.forces[j].end());
          }
          const std::size_t count = r.force_t.size();
          f["t"] = to_numpy(std::move(r.force_t));
          f["site"] = to_numpy(std::move(sites));
          f["force"] = to_numpy_2d(std::move(values), config.force_sites.size(), count);
          out["forces"] = f;
        }
        out["energy_map"] = py::none();
        if (config.map_samples > 0) {
          py::dict e;
          std::vector<long long> sites;
          for (std::size_t c = 0; c < r.map_columns; ++c)
            sites.push_back(static_cast<long long>(c * config.map_stride + 1));
          const std::size_t rows = r.map_t.size();
          e["t"] = to_numpy(std::move(r.map_t));
          e["site"] = to_numpy(std::move(sites));
          e["energy"] = to_numpy_2d(std::move(r.map_energy), rows, r.map_columns);
          out["energy_map"] = e;
        }
        out["spectral_density"] = py::none();
        if (config.spectrum_samples > 0) {
          py::dict g;
          g["freq_khz"] = to_numpy(std::move(r.spectrum_khz));
          g["g"] = to_numpy(std::move(r.spectrum));
          out["spectral_density"] = g;
        }
        out["wall_energy"] = r.wall_energy;
        out["reached_walls"] = r.reached_walls;
        out["energy_guard_time"] = r.energy_guard_time < 0 ? py::object(py::none()) : py::float_(r.energy_guard_time);
        out["steps"] = r.steps;
        out["seconds"] = r.seconds;
        out["metadata"] = to_python(meta);
        return wrap_result("SpreadingRun", out);
      },
      py::arg("chain"), py::kw_only(), py::arg("ic") = "displacement", py::arg("alpha") = 1e-7,
      py::arg("beta") = "match", py::arg("site") = py::none(), py::arg("T") = 1e-2, py::arg("dt") = 1e-6,
      py::arg("force_law") = "hertz", py::arg("integrator") = "saba2c", py::arg("samples") = 200,
      py::arg("sampling") = "log", py::arg("fit") = py::make_tuple(4e-3, 1e-2), py::arg("kappa") = 0.1,
      py::arg("forces_at") = py::none(), py::arg("force_samples") = 1000, py::arg("energy_map") = false,
      py::arg("map_samples") = 500, py::arg("map_stride") = 1, py::arg("spectral_density") = false,
      py::arg("spectrum_samples") = 2000, py::arg("active_window") = true, py::arg("window_threshold") = 1e-30,
      py::arg("reference_max_step") = 0.01e-6, py::arg("max_energy_error") = 1e-3, py::arg("energy_guard") = "stop",
      py::arg("progress") = false,
      (std::string("Energy spreading after a single-site kick in one chain (SPEC §4), integrated to T: the spreading "
                   "tool for one realization.\n\n    chain: a granular.Chain (F0 = 0 is the sonic vacuum)\n") +
       dynamics_doc +
       "    forces_at: beads (from 1) whose force [N] is recorded at force_samples uniform times\n"
       "    energy_map: record E_n(t) at map_samples uniform times, map_stride beads per column\n"
       "    spectral_density: g(nu) of u_n(t) sampled at spectrum_samples uniform times\n"
       "Returns a granular.SpreadingRun: t [s], m2 (second moment [beads^2]), ipr (P^-1 of the energy), energy_error, "
       "gamma/eta fits, final_state (u [m], v [m/s], energy [J], force [N] per bead), forces, energy_map, "
       "spectral_density, metadata. Releases the GIL.")
          .c_str());

  m.def(
      "transport",
      [](const std::string& disorder, long long N, double q, double xi, double F0, double R1, long long seed,
         long long realizations, const std::string& ic, double alpha, const py::object& beta, const py::object& site,
         double T, double dt, const std::string& force_law, const std::string& integrator, long long samples,
         const std::string& sampling, const py::object& fit, double kappa, bool active_window, double window_threshold,
         double reference_max_step, double max_energy_error, const std::string& energy_guard, bool profile,
         long long threads, const py::object& checkpoint, bool resume, bool progress) {
        const DynamicsKeywords k{T,
                                 dt,
                                 force_law,
                                 integrator,
                                 sampling,
                                 energy_guard,
                                 samples,
                                 active_window,
                                 window_threshold,
                                 reference_max_step,
                                 max_energy_error};
        TransportCase c;
        c.disorder = disorder_of(disorder);
        c.q = q;
        c.xi = xi;
        c.n = checked_size(N, "N", 2, 100000000);
        c.precompression = F0;
        c.r1 = R1;
        c.seed = checked_size(seed, "seed");
        c.realizations = checked_size(realizations, "realizations", 1);
        c.dynamics = spreading_config(k);
        validate(c.dynamics, c.n);
        if (!(kappa > 0) || !std::isfinite(kappa))
          bad_value("kappa", " " + format_number(kappa) + ": must be finite and > 0");
        const FitWindow w = fit_window(fit, c.dynamics);
        c.kick = parse_kick(ic);
        c.alpha = alpha;
        const Beta b = beta_of(beta);
        c.match_beta = c.kick == Kick::velocity && b.match;
        c.site = kicked_site(site, c.n);
        c.profile_realizations = profile ? c.realizations : 0;
        c.fit = w.possible;
        c.fit_begin = w.begin;
        c.fit_end = w.end;
        c.criterion.kappa = kappa;
        c.criterion.t_start = w.begin;
        const ChainParameters p = {.N = c.n, .q = q, .xi = xi, .seed = c.seed, .realization = 0, .F0 = F0, .R1 = R1};
        validate(p);
        c.beta = 0;                      // a displacement kick has none (the checkpoint's identity, as the tool's)
        if (c.kick == Kick::velocity) {  // the β of realization 0, as the tool reports it
          const Chain first = random_chain(c.disorder, p);
          c.beta =
              b.match ? matched_velocity(make_force_law(c.dynamics.force_law, first), first, c.site, alpha) : b.value;
        }
        validate(c);
        const int thread_request = static_cast<int>(checked_size(threads, "threads", 0, 4096));
        const std::string log = checkpoint.is_none() ? std::string() : py::str(checkpoint).cast<std::string>();
        if (resume && log.empty()) bad_value("resume", ": needs checkpoint= (the file of the interrupted run)");

        TransportSummary s;
        run_long("transport", c.realizations, progress, [&](const LongRun& control) {
          StudyRunOptions run;
          run.threads = thread_request;
          run.checkpoint = log;
          run.resume = resume;
          run.progress = control.meter;
          run.cancelled = control.cancelled;
          s = run_transport_study(c, run);
        });
        if (!log.empty())
          CheckpointLog::remove_all(log);  // finished: the result is in memory, as the tool's in its files

        nlohmann::json meta = metadata_head("transport");
        nlohmann::json chain = {{"F0_N", F0},
                                {"material", material_json(steel)},
                                {"walls", "flat, same material as the beads"},
                                {"R1_m", R1},
                                {"xi", xi},
                                {"disorder", to_string(c.disorder)},
                                {"q", q},
                                {"seed", c.seed},
                                {"realization", 0},
                                {"N", c.n}};
        meta["parameters"] = dynamics_parameters(ic, c.site, alpha, c.beta, c.match_beta, k, w, kappa);
        meta["parameters"]["chain"] = chain;
        meta["parameters"]["realizations"] = c.realizations;
        meta["seed"] = c.seed;
        for (const char* key : {"gamma", "gamma_err", "eta", "eta_err", "power_law"}) meta[key] = nullptr;
        py::dict out;
        out["gamma"] = py::none();
        out["eta"] = py::none();
        if (c.fit) {
          meta["gamma"] = s.gamma.exponent.value, meta["gamma_err"] = s.gamma.exponent.error;
          meta["eta"] = s.eta.exponent.value, meta["eta_err"] = s.eta.exponent.error;
          meta["power_law"] = s.gamma.verdict.power_law;
          meta["max_log_derivative_deviation"] = s.gamma.verdict.worst_deviation;
          out["gamma"] = analysis_dict(s.gamma);
          out["eta"] = analysis_dict(s.eta);
        }
        meta["ensemble"] = {{"realizations", s.realizations},
                            {"threads", thread_request},
                            {"mpi_ranks", MpiContext::instance().size()},
                            {"max_energy_error", s.max_energy_error},
                            {"reached_walls", s.reached_walls},
                            {"eta_power_law", s.eta.verdict.power_law}};
        out["t"] = to_numpy(std::move(s.t));
        out["m2"] = to_numpy(std::move(s.m2.mean));
        out["m2_se"] = to_numpy(std::move(s.m2.standard_error));
        out["ipr"] = to_numpy(std::move(s.ipr.mean));
        out["ipr_se"] = to_numpy(std::move(s.ipr.standard_error));
        out["energy_error"] = to_numpy(std::move(s.energy_error.mean));
        out["energy_error_se"] = to_numpy(std::move(s.energy_error.standard_error));
        out["profile"] = py::none();
        if (profile) {
          py::dict prof;
          prof["energy"] = to_numpy(std::move(s.profile.mean));
          prof["energy_se"] = to_numpy(std::move(s.profile.standard_error));
          out["profile"] = prof;
        }
        out["max_energy_error"] = s.max_energy_error;
        out["reached_walls"] = s.reached_walls;
        out["realizations"] = s.realizations;
        out["metadata"] = to_python(meta);
        return wrap_result("Transport", out);
      },
      py::kw_only(), py::arg("disorder") = "A", py::arg("N") = 2501, py::arg("q") = 0.5, py::arg("xi") = 0.5,
      py::arg("F0") = 10.0, py::arg("R1") = paper_r1, py::arg("seed") = 1, py::arg("realizations") = 100,
      py::arg("ic") = "displacement", py::arg("alpha") = 1e-7, py::arg("beta") = "match", py::arg("site") = py::none(),
      py::arg("T") = 1e-2, py::arg("dt") = 1e-6, py::arg("force_law") = "hertz", py::arg("integrator") = "saba2c",
      py::arg("samples") = 200, py::arg("sampling") = "log", py::arg("fit") = py::make_tuple(4e-3, 1e-2),
      py::arg("kappa") = 0.1, py::arg("active_window") = true, py::arg("window_threshold") = 1e-30,
      py::arg("reference_max_step") = 0.01e-6, py::arg("max_energy_error") = 1e-3, py::arg("energy_guard") = "stop",
      py::arg("profile") = false, py::arg("threads") = 0, py::arg("checkpoint") = py::none(), py::arg("resume") = false,
      py::arg("progress") = false,
      (std::string("An ensemble of spreading runs: realizations 0..R-1 of seed `seed` of a disordered chain, each "
                   "kicked and integrated to T, averaged and fitted (the spreading tool's --realizations R).\n\n"
                   "    disorder, N, q, xi, F0 [N], R1 [m], seed: the chains, as granular.random_chain's\n"
                   "    realizations: R\n") +
       dynamics_doc +
       "    profile: also average the site energies E_n(T)\n"
       "    threads: worker threads (0: every core); results do not depend on it\n"
       "    checkpoint: a file logging each finished realization (removed once the run completes); resume=True "
       "continues an interrupted run from it and gives exactly the uninterrupted result\n"
       "    progress: draw a progress bar\n"
       "Returns a granular.Transport: t [s], m2, m2_se, ipr, ipr_se, energy_error(_se), profile, gamma, eta, "
       "max_energy_error, reached_walls, realizations, metadata. Releases the GIL; Ctrl-C stops it after the "
       "realizations in flight (KeyboardInterrupt), leaving the checkpoint to resume from.")
          .c_str());

  m.def(
      "exponent_table",
      [](const std::vector<std::string>& chains, const py::object& F0, const std::vector<std::string>& ic, long long N,
         long long site, double xi, double q, double T, double dt, double alpha, const py::object& beta,
         const std::string& integrator, long long realizations, long long seed, long long samples,
         const py::object& fit, double kappa, const py::object& profile_F0, long long profile_realizations,
         bool active_window, long long threads, const py::object& checkpoint, bool resume, bool progress) {
        ExponentTableConfig config;
        config.chains.clear();
        for (const auto& name : chains) {
          try {
            config.chains.push_back(parse_disorder(name));
          } catch (const InvalidInput&) {
            bad_value("chains", " '" + name + "': expected h, A, RDM1 or RDM2");
          }
        }
        if (config.chains.empty()) bad_value("chains", ": none given");
        if (ic.empty()) bad_value("ic", ": none given");
        config.precompressions = number_list(F0, "F0", 0);
        config.kicks.clear();
        for (const auto& name : ic) config.kicks.push_back(parse_kick(name));
        config.profile_precompressions =
            profile_F0.is_none() ? std::vector<double>{} : number_list(profile_F0, "profile_F0", 0);
        config.profile_realizations = checked_size(profile_realizations, "profile_realizations");
        TransportCase& base = config.base;
        base.n = checked_size(N, "N", 2, 100000000);
        checked_size(site, "site", 0, N);
        base.site = site == 0 ? (base.n - 1) / 2 : static_cast<std::size_t>(site - 1);
        base.xi = xi;
        base.q = q;
        base.alpha = alpha;
        const Beta b = beta_of(beta);
        base.match_beta = b.match;
        if (!b.match) {
          if (!(b.value != 0)) bad_value("beta", ": a non-zero number [m/s] or 'match'");
          base.beta = b.value;
        }
        base.dynamics.duration = T;
        base.dynamics.time_step = dt;
        if (integrator != "reference") parse_scheme(integrator, "integrator");
        base.dynamics.integrator = integrator;
        base.dynamics.samples = checked_size(samples, "samples", 2, 100000000);
        base.dynamics.window.enabled = active_window;
        base.seed = checked_size(seed, "seed");
        base.realizations = checked_size(realizations, "realizations", 1);
        const std::vector<double> f = double_vector(fit, "fit");
        if (f.size() != 2 || !(f[0] < f[1])) bad_value("fit", ": expected (start, stop) [s] with start < stop");
        base.fit_begin = f[0];
        base.fit_end = f[1];
        base.criterion.kappa = kappa;
        base.criterion.t_start = f[0];
        const auto cases = exponent_cases(config);
        for (const auto& c : cases) validate(c);
        std::size_t total = 0;
        for (const auto& c : cases) total += c.realizations;
        const int thread_request = static_cast<int>(checked_size(threads, "threads", 0, 4096));
        const std::string prefix = checkpoint.is_none() ? std::string() : py::str(checkpoint).cast<std::string>();
        if (resume && prefix.empty()) bad_value("resume", ": needs checkpoint= (the prefix of the interrupted run)");

        std::vector<ExponentCell> cells;
        run_long("exponent_table", total, progress, [&](const LongRun& control) {
          ExponentRunOptions run;
          run.threads = thread_request;
          run.checkpoint_prefix = prefix;
          run.resume = resume;
          run.progress = 0;
          run.meter = control.meter;
          run.cancelled = control.cancelled;
          cells = run_exponent_table(config, run);
        });
        if (!prefix.empty())
          for (std::size_t i = 0; i < cells.size(); ++i) CheckpointLog::remove_all(prefix + "." + std::to_string(i));

        py::list table, curves, profiles;
        nlohmann::json described = nlohmann::json::array();
        for (const auto& cell : cells) {
          const auto& d = cell.definition;
          const auto& s = cell.summary;
          py::dict row;
          row["ic"] = to_string(d.kick);
          row["F0"] = d.precompression;
          row["disorder"] = to_string(d.disorder);
          row["gamma"] = s.gamma.exponent.value;
          row["gamma_err"] = s.gamma.exponent.error;
          row["eta"] = s.eta.exponent.value;
          row["eta_err"] = s.eta.exponent.error;
          row["power_law_m2"] = s.gamma.verdict.power_law;
          row["power_law_ipr"] = s.eta.verdict.power_law;
          row["worst_deviation_m2"] = s.gamma.verdict.worst_deviation;
          row["worst_deviation_ipr"] = s.eta.verdict.worst_deviation;
          row["realizations"] = s.realizations;
          row["max_energy_error"] = s.max_energy_error;
          row["reached_walls"] = s.reached_walls;
          table.append(row);
          py::dict curve;
          curve["ic"] = row["ic"], curve["F0"] = row["F0"], curve["disorder"] = row["disorder"];
          curve["t"] = to_numpy(s.t);
          curve["m2"] = to_numpy(s.m2.mean);
          curve["m2_se"] = to_numpy(s.m2.standard_error);
          curve["ipr"] = to_numpy(s.ipr.mean);
          curve["ipr_se"] = to_numpy(s.ipr.standard_error);
          curve["energy_error"] = to_numpy(s.energy_error.mean);
          curves.append(curve);
          if (!s.profile.mean.empty()) {
            py::dict p;
            p["ic"] = row["ic"], p["F0"] = row["F0"], p["disorder"] = row["disorder"];
            p["energy"] = to_numpy(s.profile.mean);
            p["energy_se"] = to_numpy(s.profile.standard_error);
            profiles.append(p);
          }
          described.push_back(describe(d));
        }
        std::string chain_list;
        for (const auto& name : chains) chain_list += (chain_list.empty() ? "" : ",") + name;
        std::string kick_list;
        for (const auto& name : ic) kick_list += (kick_list.empty() ? "" : ",") + name;
        nlohmann::json meta = metadata_head("exponent_table");
        meta["parameters"] = {{"chains", chain_list}, {"F0", config.precompressions},
                              {"ic", kick_list},      {"fit_s", f},
                              {"kappa", kappa},       {"log_step", base.criterion.log_step},
                              {"threads", threads},   {"mpi_ranks", MpiContext::instance().size()}};
        meta["cases"] = described;
        py::dict out;
        out["table"] = table;
        out["curves"] = curves;
        out["profiles"] = profiles;
        out["metadata"] = to_python(meta);
        return wrap_result("ExponentTable", out);
      },
      py::kw_only(), py::arg("chains") = std::vector<std::string>{"h", "A", "RDM1", "RDM2"},
      py::arg("F0") = std::vector<double>{10, 0.5, 0.1, 0.01, 0},
      py::arg("ic") = std::vector<std::string>{"displacement", "velocity"}, py::arg("N") = 2501, py::arg("site") = 0,
      py::arg("xi") = 0.5, py::arg("q") = 0.5, py::arg("T") = 1e-2, py::arg("dt") = 1e-6, py::arg("alpha") = 1e-7,
      py::arg("beta") = py::float_(8e-3), py::arg("integrator") = "saba2c", py::arg("realizations") = 500,
      py::arg("seed") = 1, py::arg("samples") = 100, py::arg("fit") = py::make_tuple(4e-3, 1e-2),
      py::arg("kappa") = 0.1, py::arg("profile_F0") = std::vector<double>{10, 0.1, 0},
      py::arg("profile_realizations") = 100, py::arg("active_window") = true, py::arg("threads") = 0,
      py::arg("checkpoint") = py::none(), py::arg("resume") = false, py::arg("progress") = false,
      "The paper's transport study (the exponents tool): gamma (m2 ~ t^gamma) and eta (P^-1 ~ t^-eta) for every "
      "chain kind x F0 x kick, each an ensemble of `realizations` (h runs one: it is deterministic).\n\n"
      "    chains: kinds among 'h', 'A', 'RDM1', 'RDM2'; F0: precompressions [N] (0: sonic vacuum); ic: kicks\n"
      "    N, site (from 1; 0 = the centre), xi, q, T [s], dt [s], alpha [m], beta [m/s] or 'match', integrator\n"
      "    realizations, seed, samples (log-spaced from tau to T), fit (start, stop) [s], kappa\n"
      "    profile_F0, profile_realizations: F0s whose E_n(T) is averaged, over how many realizations (None: none)\n"
      "    active_window; threads (0: every core); checkpoint: a prefix, case i logs to <prefix>.<i> (removed once "
      "done); resume=True continues an interrupted table; progress: a progress bar\n"
      "Returns a granular.ExponentTable (table rows as the tool's CSV, curves, profiles, metadata). Releases the "
      "GIL; Ctrl-C stops it resumably (KeyboardInterrupt).");
}

}  // namespace granular::python
