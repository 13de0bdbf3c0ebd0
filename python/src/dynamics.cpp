// The nonlinear dynamics: one spreading run (granular.spreading), an ensemble of them
// (granular.transport, the spreading tool's --realizations) and the paper's exponent table
// (granular.exponent_table). Kept thin on purpose: keywords to a TransportCase by the rule the
// tools use too (study/transport_choices.hpp), results to dicts of NumPy arrays and the
// library's own JSON and CSV writers, wrapped by granular._results. The library's own run with
// observers is granular.spread (observers.cpp).
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "bindings.hpp"
#include "granular/code_identity.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/spreading.hpp"
#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/error.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/number_format.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/study/chain_length_rule.hpp"
#include "granular/study/exponent_table.hpp"
#include "granular/study/paper_comparison.hpp"
#include "granular/study/scheme_choice.hpp"
#include "granular/study/spreading_files.hpp"
#include "granular/study/time_step_rule.hpp"
#include "granular/study/transport_choices.hpp"
#include "granular/study/transport_study.hpp"

namespace granular::python {
namespace {

/// The keywords every kicked-chain call shares: the spreading and exponents tools' dynamics options.
struct DynamicsKeywords {
  double alpha;
  py::object beta, site;
  std::string centre;
  double T;
  py::object dt;  // None: the time-step rule's default (time_step_rule.hpp)
  std::string integrator, force_law;
  long long samples;
  std::string sampling;
  py::object fit;
  double fit_step, t_star, kappa;
  long long bootstrap;
  bool active_window;
  double window_threshold, reference_max_step, max_energy_error;
  std::string energy_guard;
};

/// Fills `c` from the keywords: granular::apply(TransportChoices), as the tools do from their
/// options, once the keywords only Python has are read (beta a number or 'match', site None,
/// fit a pair). Needs c.chain (for `site`).
void apply(const DynamicsKeywords& k, TransportCase& c) {
  TransportChoices choices;
  choices.alpha = k.alpha;
  if (py::isinstance<py::str>(k.beta)) {
    if (k.beta.cast<std::string>() != "match")
      bad_value("beta", " '" + k.beta.cast<std::string>() + "': a number [m/s] or 'match'");
    choices.beta.reset();
  } else {
    choices.beta = finite(k.beta.cast<double>(), "beta");
  }
  choices.site = k.site.is_none() ? 0 : k.site.cast<long long>();
  choices.centre = k.centre;
  choices.duration = k.T;
  choices.time_step = k.dt.is_none() ? 1e-6 : finite(k.dt.cast<double>(), "dt");
  choices.integrator = k.integrator == "auto" ? "saba2c" : k.integrator;  // 'auto': settled with the step
  choices.force_law = k.force_law;
  choices.samples = static_cast<long long>(checked_size(k.samples, "samples", 2, 100000000));
  choices.sampling = k.sampling;
  choices.active_window = k.active_window;
  choices.window_threshold = k.window_threshold;
  choices.reference_max_step = k.reference_max_step;
  choices.max_energy_error = k.max_energy_error;
  choices.energy_guard = k.energy_guard;
  const std::vector<double> fit = double_vector(k.fit, "fit");
  if (fit.size() != 2) bad_value("fit", ": expected (start, stop) [s] with 0 < start < stop");
  choices.fit_begin = fit[0];
  choices.fit_end = fit[1];
  choices.fit_step = k.fit_step;
  choices.t_star = k.t_star;
  choices.kappa = k.kappa;
  choices.bootstrap = static_cast<long long>(checked_size(k.bootstrap, "bootstrap", 2, 100000000));
  granular::apply(choices, c);
}

/// The keyword arguments of DynamicsKeywords, with the tools' defaults, in this order.
#define GRANULAR_DYNAMICS_ARGS                                                                                      \
  py::arg("alpha") = 1e-7, py::arg("beta") = py::float_(paper_beta), py::arg("site") = py::none(),                  \
  py::arg("centre") = "site", py::arg("T") = 1e-2, py::arg("dt") = py::none(), py::arg("integrator") = "saba2c",    \
  py::arg("force_law") = "hertz", py::arg("samples") = 100, py::arg("sampling") = "log",                            \
  py::arg("fit") = py::make_tuple(4e-3, 1e-2), py::arg("fit_step") = 1e-5, py::arg("t_star") = 4e-3,                \
  py::arg("kappa") = 0.1, py::arg("bootstrap") = 1000, py::arg("active_window") = true,                             \
  py::arg("window_threshold") = 1e-30, py::arg("reference_max_step") = 0.01e-6, py::arg("max_energy_error") = 1e-3, \
  py::arg("energy_guard") = "stop"

/// The keyword arguments of BeyondChoices (transport_choices.hpp) shared by the three calls, with the tools' defaults.
#define GRANULAR_BEYOND_ARGS \
  py::arg("damping_time") = 0.0, py::arg("kk_gamma") = 0.0, py::arg("mle") = false, py::arg("renormalize") = 10

const char* dynamics_doc =
    "    alpha: displacement kick [m]; beta: velocity kick [m/s] (the paper's 8e-3 for every F0) or 'match' (the "
    "energy of alpha on each chain)\n"
    "    site: kicked bead n0, counting from 1 as the tools do (None or 0: the centre, (N+1)/2)\n"
    "    centre: m2 about the kicked 'site' (the paper's n_c) or the energy 'centroid'; both are computed, this one "
    "gives gamma\n"
    "    T: duration [s], a whole number of dt; dt: time step tau [s]; None: 1 us, or 1 us/k where the stability "
    "rule tau <= h*/omega_max needs it (a dt past that limit is a ValueError naming the largest stable one; the "
    "rule and its numbers are in metadata['time_step_rule'])\n"
    "    integrator: 'saba2c' | 'saba2' | 'aba864' | 'srkn14a' | 'reference' | 'auto' (the cheapest scheme and step "
    "keeping the energy error at SABA2C's at 1 us: SRKN14a at 5 us where no contact can open, else SABA2C; no dt "
    "with it; the choice in metadata['time_step_rule']['integrator_choice']); force_law: 'hertz' | 'fpu' | 'linear'\n"
    "    samples, sampling: sample times outside the fit window ('log': tau..T, 'uniform': 0..T)\n"
    "    fit: (start, stop) [s] of gamma (m2 ~ t^gamma) and eta (P^-1 ~ t^-eta), sampled every fit_step [s] inside\n"
    "    t_star, kappa: 'not a power law' when |L_d - gamma| >= kappa after t_star [s] (then the mean L_d is shown)\n"
    "    bootstrap: resamples of the realization bootstrap of gamma and eta (ensembles)\n"
    "    active_window, window_threshold: integrate only where the wave has arrived (results equal the full chain's)\n"
    "    reference_max_step: largest step of the reference integrator [s] (0: none)\n"
    "    max_energy_error, energy_guard: relative energy error that stops the run ('stop': NumericalError) or is only "
    "reported ('warn'); 0 = unwatched\n";

const char* beyond_doc =
    "    damping_time: on-site viscous damping time tau_d [s], force -(m/tau_d) du/dt on each bead; 0 = none\n"
    "    kk_gamma: Kuwabara-Kono contact damping gamma_KK [s], bond force A[d]^{3/2} + gamma_KK A [d]^{1/2} dd/dt "
    "while in contact; 0 = none. With either, energy_error is |H + dissipated - H0|/H0 and the whole chain is "
    "integrated\n"
    "    mle: also the maximal Lyapunov exponent X1(t) [1/s] by the tangent map of the same scheme (conservative "
    "runs only: not with damping or integrator='reference'); renormalize: steps between renormalizations of the "
    "deviation vector (>= 1)\n";

/// The exponents as the tools' JSON carries them: gamma, gamma_err, gamma_real_err, eta, eta_err,
/// eta_real_err, power_law (all None without a fit), m2_centre and every report under "exponents".
nlohmann::json exponent_keys(const std::optional<TransportExponents>& e, SpreadCentre centre) {
  nlohmann::json out;
  for (const char* key : {"gamma", "gamma_err", "gamma_real_err", "eta", "eta_err", "eta_real_err", "power_law"})
    out[key] = nullptr;
  if (e) out.update(to_json(*e, centre));
  return out;
}

py::object wrap_result(const char* type, py::dict values) {
  return py::module_::import("granular._results").attr(type)(values);
}

py::object csv_text(const std::function<void(std::ostream&)>& write) {
  std::ostringstream out;
  write(out);
  return py::str(out.str());
}

}  // namespace

void bind_dynamics(py::module_& m) {
  m.def(
      "spreading",
      [](const PyChain& chain, const std::string& ic, double alpha, const py::object& beta, const py::object& site,
         const std::string& centre, double T, const py::object& dt, const std::string& integrator,
         const std::string& force_law, long long samples, const std::string& sampling, const py::object& fit,
         double fit_step, double t_star, double kappa, long long bootstrap, bool active_window, double window_threshold,
         double reference_max_step, double max_energy_error, const std::string& energy_guard,
         const py::object& forces_at, long long force_samples, bool energy_map, long long map_samples,
         long long map_stride, bool spectral_density, long long spectrum_samples, const std::string& spectrum_of,
         bool progress, long mode, double mode_khz, double energy, double damping_time, double kk_gamma, bool mle,
         long long renormalize, long long deviation_samples) {
        const DynamicsKeywords k{alpha,
                                 beta,
                                 site,
                                 centre,
                                 T,
                                 dt,
                                 integrator,
                                 force_law,
                                 samples,
                                 sampling,
                                 fit,
                                 fit_step,
                                 t_star,
                                 kappa,
                                 bootstrap,
                                 active_window,
                                 window_threshold,
                                 reference_max_step,
                                 max_energy_error,
                                 energy_guard};
        const nlohmann::json& described = chain.description;
        TransportCase c;
        c.chain = chain.recipe;
        c.kick = parse_kick(ic);
        c.realizations = 1;
        c.profile_realizations = 0;
        apply(k, c);
        SpreadingConfig& d = c.dynamics;
        granular::apply(BeyondChoices{damping_time, kk_gamma, mle, renormalize, deviation_samples}, d);
        c.fit = c.fit_end <= d.duration * (1 + 1e-12);  // a window beyond T: no exponents
        if (!forces_at.is_none())
          for (double s : double_vector(forces_at, "forces_at")) {
            if (s != std::floor(s) || s < 1 || s > static_cast<double>(c.chain.size()))
              bad_value("forces_at", " " + format_number(s) + ": outside the chain of " +
                                         std::to_string(c.chain.size()) + " beads (1..N)");
            d.force_sites.push_back(static_cast<std::size_t>(s) - 1);
          }
        d.force_samples = checked_size(force_samples, "force_samples", 1, 100000000);
        d.map_samples = energy_map ? checked_size(map_samples, "map_samples", 2, 100000000) : 0;
        d.map_stride = checked_size(map_stride, "map_stride", 1, 100000000);
        d.spectrum_samples = spectral_density ? checked_size(spectrum_samples, "spectrum_samples", 2, 100000000) : 0;
        try {
          d.spectrum_source = parse_spectrum_source(spectrum_of);
        } catch (const InvalidInput&) {
          bad_value("spectrum_of", " '" + spectrum_of + "': displacement or velocity");
        }
        if ((mode != 0 || mode_khz >= 0 || energy != 0) && c.kick != Kick::mode)
          bad_value("mode", ": mode, mode_khz and energy only with ic='mode'");
        c.mode = {.mode = mode, .near_khz = mode_khz, .energy = energy, .amplitude = 0};
        validate(c);
        // τ by the stability rule on the chain's recipe: every realization of a random chain (as the
        // tool's --disorder), this very chain for a given one (as the tool's --config/--radii).
        const nlohmann::json step_rule = settle_scheme_and_step(c, integrator == "auto", !dt.is_none());
        if (const std::string w = duration_warning(c, "T"); !w.empty()) warn({w});  // after the errors
        const KickedChain kicked = kick(c, chain.chain);

        SpreadingResult r;
        std::optional<TransportExponents> exponents;
        run_long("spreading", 1, progress, [&](const LongRun& control) {
          r = run_spreading(chain.chain, kicked.initial, spreading_config(c));
          if (c.fit) exponents = transport_exponents(c, r.t, r.m2, r.m2_centroid, r.ipr);
          control.meter->advance();
        });

        nlohmann::json meta = metadata_head("spreading");
        meta["parameters"] = describe(c);
        meta["parameters"]["chain"] = described;
        if (c.kick == Kick::velocity) meta["parameters"]["beta_m_s"] = kicked.beta;  // the β used
        if (c.kick == Kick::mode) meta["parameters"]["mode_used"] = to_json(kicked.mode);
        meta["seed"] = c.chain.seed;
        const nlohmann::json fitted = exponent_keys(exponents, c.centre);
        meta.update(fitted);
        meta["time_step_rule"] = step_rule;
        meta["run"] = describe_run(r, described.value("realization", nlohmann::json(0)));
        if (d.spectrum_samples > 0)
          meta["spectrum"] = {{"of", to_string(d.spectrum_source)}, {"samples", d.spectrum_samples}};

        py::dict out = to_python(fitted);
        std::vector<std::string> said = notes(c);
        for (const auto& w : warnings(r, d)) said.push_back(w);
        out["warnings"] = warn(said);
        out["t"] = to_numpy(std::move(r.t));
        out["m2"] = to_numpy(std::move(r.m2));
        out["m2_centroid"] = to_numpy(std::move(r.m2_centroid));
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
        // Beyond the paper: the columns `dissipated` and `mle` of the tool's CSV, and its --deviation file.
        out["dissipated"] =
            r.dissipated.empty() ? py::object(py::none()) : py::object(to_numpy(std::move(r.dissipated)));
        out["mle"] = r.mle.empty() ? py::object(py::none()) : py::object(to_numpy(std::move(r.mle)));
        out["deviation"] = py::none();
        if (d.deviation_samples > 0) {
          py::dict w;
          const std::size_t rows = r.deviation_t.size(), n = c.chain.size();
          std::vector<long long> sites;
          for (std::size_t j = 0; j < n; ++j) sites.push_back(static_cast<long long>(j + 1));
          w["t"] = to_numpy(std::move(r.deviation_t));
          w["site"] = to_numpy(std::move(sites));
          w["share"] = to_numpy_2d(std::move(r.deviation), rows, n);
          out["deviation"] = w;
        }
        out["forces"] = py::none();
        if (!d.force_sites.empty()) {
          py::dict f;
          std::vector<long long> sites;
          std::vector<double> values;
          for (std::size_t j = 0; j < d.force_sites.size(); ++j) {
            sites.push_back(static_cast<long long>(d.force_sites[j] + 1));
            values.insert(values.end(), r.forces[j].begin(), r.forces[j].end());
          }
          const std::size_t count = r.force_t.size();
          f["t"] = to_numpy(std::move(r.force_t));
          f["site"] = to_numpy(std::move(sites));
          f["force"] = to_numpy_2d(std::move(values), d.force_sites.size(), count);
          out["forces"] = f;
        }
        out["energy_map"] = py::none();
        if (d.map_samples > 0) {
          py::dict e;
          std::vector<long long> sites;
          for (std::size_t j = 0; j < r.map_columns; ++j) sites.push_back(static_cast<long long>(j * d.map_stride + 1));
          const std::size_t rows = r.map_t.size();
          e["t"] = to_numpy(std::move(r.map_t));
          e["site"] = to_numpy(std::move(sites));
          e["energy"] = to_numpy_2d(std::move(r.map_energy), rows, r.map_columns);
          out["energy_map"] = e;
        }
        out["spectral_density"] = py::none();
        if (d.spectrum_samples > 0) {
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
      py::arg("chain"), py::kw_only(), py::arg("ic") = "displacement", GRANULAR_DYNAMICS_ARGS,
      py::arg("forces_at") = py::none(), py::arg("force_samples") = 1000, py::arg("energy_map") = false,
      py::arg("map_samples") = 500, py::arg("map_stride") = 1, py::arg("spectral_density") = false,
      py::arg("spectrum_samples") = 2000, py::arg("spectrum_of") = "displacement", py::arg("progress") = false,
      py::arg("mode") = 0, py::arg("mode_khz") = -1.0, py::arg("energy") = 0.0, GRANULAR_BEYOND_ARGS,
      py::arg("deviation_samples") = 0,
      (std::string("Energy spreading after a single-site kick in one chain (SPEC §4), integrated to T: the spreading "
                   "tool for one realization.\n\n    chain: a granular.Chain (F0 = 0 is the sonic vacuum)\n"
                   "    ic: 'displacement' (u = alpha at the site) | 'velocity' (v = beta at the site) | 'mode' (a "
                   "linear mode of the chain, u = M^-1/2 w from rest: number `mode` 1..N or the one nearest `mode_khz` "
                   "[kHz], total energy `energy` [J] or, without it, largest |u_n| = alpha)\n") +
       dynamics_doc + beyond_doc +
       "    deviation_samples: with mle, where the deviation vector sits along the chain (the tool's --deviation) at "
       "this many uniform times 0..T (0 = none, else >= 2)\n"
       "    forces_at: beads (from 1) whose force [N] is recorded at force_samples uniform times\n"
       "    energy_map: record E_n(t) at map_samples uniform times, map_stride beads per column\n"
       "    spectral_density: g(nu) of u_n(t) (spectrum_of='displacement', the paper's) or of v_n(t) ('velocity') "
       "sampled at spectrum_samples uniform times\n"
       "Returns a granular.SpreadingRun: t [s], m2 and m2_centroid (second moments about the kicked bead and about "
       "the energy centroid [beads^2]), ipr (P^-1 of the energy), energy_error, gamma, eta (the shown values, as the "
       "tool's JSON) with every report under 'exponents', final_state (u [m], v [m/s], energy [J], force [N] per "
       "bead), forces, energy_map, spectral_density, dissipated (energy removed by the damping by t [J], at t; None "
       "without damping), mle (X1(t) [1/s] at t; None without mle), deviation (t [s], site (from 1), share (times x "
       "beads: the share of |w|^2 = |du|^2 + (t_unit dv)^2, t_unit = 1 us, on each bead, rows summing to 1; "
       "share.ravel() is the "
       "tool's --deviation column) or None), warnings, metadata. Releases the GIL.")
          .c_str());

  m.def(
      "transport",
      [](const std::string& disorder, long long N, double q, double xi, double F0, double R1, long long seed,
         long long realizations, const std::string& ic, double alpha, const py::object& beta, const py::object& site,
         const std::string& centre, double T, const py::object& dt, const std::string& integrator,
         const std::string& force_law, long long samples, const std::string& sampling, const py::object& fit,
         double fit_step, double t_star, double kappa, long long bootstrap, bool active_window, double window_threshold,
         double reference_max_step, double max_energy_error, const std::string& energy_guard, bool profile,
         long long threads, const py::object& checkpoint, bool resume, bool resume_other_version, bool progress,
         double damping_time, double kk_gamma, bool mle, long long renormalize) {
        const DynamicsKeywords k{alpha,
                                 beta,
                                 site,
                                 centre,
                                 T,
                                 dt,
                                 integrator,
                                 force_law,
                                 samples,
                                 sampling,
                                 fit,
                                 fit_step,
                                 t_star,
                                 kappa,
                                 bootstrap,
                                 active_window,
                                 window_threshold,
                                 reference_max_step,
                                 max_energy_error,
                                 energy_guard};
        TransportCase c;
        c.chain = {.disorder = disorder_of(disorder),
                   .q = q,
                   .xi = xi,
                   .R1 = R1,
                   .N = checked_size(N, "N", 2, 100000000),
                   .F0 = F0,
                   .seed = checked_size(seed, "seed")};
        c.kick = parse_kick(ic);
        c.realizations = checked_size(realizations, "realizations", 1);
        c.profile_realizations = profile ? c.realizations : 0;
        apply(k, c);
        granular::apply(BeyondChoices{damping_time, kk_gamma, mle, renormalize}, c.dynamics);
        c.fit = c.fit_end <= c.dynamics.duration * (1 + 1e-12);
        validate(c);
        const nlohmann::json step_rule = settle_scheme_and_step(c, integrator == "auto", !dt.is_none());
        if (const std::string w = duration_warning(c, "T"); !w.empty()) warn({w});  // after the errors
        const int thread_request = static_cast<int>(checked_size(threads, "threads", 0, 4096));
        const std::string log = checkpoint.is_none() ? std::string() : py::str(checkpoint).cast<std::string>();
        if ((resume || resume_other_version) && log.empty())
          bad_value("resume", ": needs checkpoint= (the file of the interrupted run)");
        // The chain of realization 0, as the tool describes it (and the β it kicks it with).
        const KickedChain first = kick(c, c.chain.chain(0));

        // Read before the run, which rewrites the checkpoint under this code's name.
        const std::string made_by = resume_other_version ? CheckpointLog::code_of(log) : std::string();
        TransportSummary s;
        run_long("transport", c.realizations, progress, [&](const LongRun& control) {
          RunOptions run;
          run.threads = thread_request;
          run.checkpoint = log;
          run.resume = resume || resume_other_version;
          run.accept_other_version = resume_other_version;
          run.progress = control.meter;
          run.cancelled = control.cancelled;
          s = run_transport_study(c, run);
        });
        if (!log.empty()) CheckpointLog::remove_all(log);  // finished: the result is in memory, as the tool's in files

        nlohmann::json meta = metadata_head("transport");
        meta["parameters"] = describe(c);
        meta["parameters"]["chain"] = describe(c.chain, 0);
        if (c.kick == Kick::velocity && !c.match_beta) meta["parameters"]["beta_m_s"] = first.beta;
        meta["seed"] = c.chain.seed;
        if (!made_by.empty())
          meta["resumed_checkpoint"] = {{"made_by", made_by},
                                        {"resumed_by", std::string(code_version()) + " (commit " + code_commit() + ")"}};
        const nlohmann::json fitted = exponent_keys(s.exponents, c.centre);
        meta.update(fitted);
        meta["ensemble"] = {{"realizations", s.realizations},
                            {"threads", thread_request},
                            {"mpi_ranks", MpiContext::instance().size()},
                            {"max_energy_error", s.max_energy_error},
                            {"reached_walls", s.reached_walls},
                            {"failed_excluded", s.excluded}};
        meta["time_step_rule"] = step_rule;

        py::dict out = to_python(fitted);
        std::vector<std::string> said = notes(c);
        for (const auto& w : warnings(s, c.dynamics)) said.push_back(w);
        out["warnings"] = warn(said);
        out["t"] = to_numpy(std::move(s.t));
        out["m2"] = to_numpy(std::move(s.m2.mean));
        out["m2_se"] = to_numpy(std::move(s.m2.standard_error));
        out["m2_centroid"] = to_numpy(std::move(s.m2_centroid.mean));
        out["m2_centroid_se"] = to_numpy(std::move(s.m2_centroid.standard_error));
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
        // With the tangent map: <X1(t)> [1/s] (the tool's column mle) and its standard error.
        const bool tangent = !s.mle.mean.empty();
        out["mle"] = tangent ? py::object(to_numpy(std::move(s.mle.mean))) : py::object(py::none());
        out["mle_se"] = tangent ? py::object(to_numpy(std::move(s.mle.standard_error))) : py::object(py::none());
        out["max_energy_error"] = s.max_energy_error;
        out["reached_walls"] = s.reached_walls;
        out["realizations"] = s.realizations;
        out["metadata"] = to_python(meta);
        return wrap_result("Transport", out);
      },
      py::kw_only(), py::arg("disorder") = "A", py::arg("N") = 2501, py::arg("q") = 0.5, py::arg("xi") = 0.5,
      py::arg("F0") = 10.0, py::arg("R1") = paper_r1, py::arg("seed") = 1, py::arg("realizations") = 100,
      py::arg("ic") = "displacement", GRANULAR_DYNAMICS_ARGS, py::arg("profile") = false, py::arg("threads") = 0,
      py::arg("checkpoint") = py::none(), py::arg("resume") = false, py::arg("resume_other_version") = false,
      py::arg("progress") = false, GRANULAR_BEYOND_ARGS,
      (std::string("An ensemble of spreading runs: realizations 0..R-1 of seed `seed` of a disordered chain, each "
                   "kicked and integrated to T, averaged and fitted (the spreading tool's --realizations R).\n\n"
                   "    disorder, N, q, xi, F0 [N], R1 [m], seed: the chains, as granular.random_chain's\n"
                   "    realizations: R; ic: 'displacement' | 'velocity'\n") +
       dynamics_doc + beyond_doc +
       "    profile: also average the site energies E_n(T)\n"
       "    threads: worker threads (0: every core); results do not depend on it\n"
       "    checkpoint: a file logging each finished realization (removed once the run completes); resume=True "
       "continues an interrupted run from it and gives exactly the uninterrupted result; a checkpoint another "
       "granular version made is refused unless resume_other_version=True (both are named in metadata)\n"
       "    progress: draw a progress bar\n"
       "Returns a granular.Transport: t [s], m2, m2_centroid, ipr, energy_error with their standard errors (_se), "
       "profile, gamma, eta (with realization errors gamma_real_err, eta_real_err from the bootstrap) and every report "
       "under 'exponents', mle and mle_se (the mean X1(t) [1/s] over realizations and its standard error; None "
       "without mle), max_energy_error, reached_walls, realizations, warnings, metadata. Releases the GIL; "
       "Ctrl-C stops it after the realizations in flight (KeyboardInterrupt), leaving the checkpoint to resume from.")
          .c_str());

  m.def(
      "exponent_table",
      [](const std::vector<std::string>& chains, const py::object& F0, const std::vector<std::string>& ic, long long N,
         double xi, double q, long long realizations, long long seed, double alpha, const py::object& beta,
         const py::object& site, const std::string& centre, double T, const py::object& dt,
         const std::string& integrator, const std::string& force_law, long long samples, const std::string& sampling,
         const py::object& fit, double fit_step, double t_star, double kappa, long long bootstrap, bool active_window,
         double window_threshold, double reference_max_step, double max_energy_error, const std::string& energy_guard,
         const py::object& profile_F0, long long profile_realizations, const py::object& compare_paper,
         long long threads, const py::object& checkpoint, bool resume, bool resume_other_version, bool progress,
         double damping_time, double kk_gamma, bool mle, long long renormalize) {
        const DynamicsKeywords k{alpha,
                                 beta,
                                 site,
                                 centre,
                                 T,
                                 dt,
                                 integrator,
                                 force_law,
                                 samples,
                                 sampling,
                                 fit,
                                 fit_step,
                                 t_star,
                                 kappa,
                                 bootstrap,
                                 active_window,
                                 window_threshold,
                                 reference_max_step,
                                 max_energy_error,
                                 energy_guard};
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
        config.precompressions = number_list(F0, "F0", 0);
        config.kicks.clear();
        for (const auto& name : ic) config.kicks.push_back(parse_kick(name));
        if (config.kicks.empty()) bad_value("ic", ": none given");
        config.profile_precompressions =
            profile_F0.is_none() ? std::vector<double>{} : number_list(profile_F0, "profile_F0", 0);
        config.profile_realizations = checked_size(profile_realizations, "profile_realizations");
        TransportCase& base = config.base;
        base.chain.N = checked_size(N, "N", 2, 100000000);
        base.chain.xi = xi;
        base.chain.q = q;
        base.chain.seed = checked_size(seed, "seed");
        base.realizations = checked_size(realizations, "realizations", 1);
        apply(k, base);
        granular::apply(BeyondChoices{damping_time, kk_gamma, mle, renormalize}, base.dynamics);
        auto cases = exponent_cases(config);
        for (const auto& c : cases) validate(c);
        const nlohmann::json step_rule = settle_scheme_and_step(cases, integrator == "auto", !dt.is_none());
        for (const auto& c : cases)  // after the errors; one warning is enough: the cases share T
          if (const std::string w = duration_warning(c, "T"); !w.empty()) {
            warn({w});
            break;
          }
        base.dynamics = cases.front().dynamics;  // τ and scheme as settled
        std::size_t total = 0;
        for (const auto& c : cases) total += c.realizations;
        const int thread_request = static_cast<int>(checked_size(threads, "threads", 0, 4096));
        const std::string prefix = checkpoint.is_none() ? std::string() : py::str(checkpoint).cast<std::string>();
        if ((resume || resume_other_version) && prefix.empty())
          bad_value("resume", ": needs checkpoint= (the prefix of the interrupted run)");
        const bool compare = py::isinstance<py::str>(compare_paper) || py::bool_(compare_paper);
        const std::string paper_path = py::isinstance<py::str>(compare_paper)
                                           ? compare_paper.cast<std::string>()
                                           : std::string(GRANULAR_SOURCE_DIR) + "/data/paper_table1_gamma.csv";
        const std::vector<PaperCell> paper = compare ? read_paper_table(paper_path) : std::vector<PaperCell>{};

        std::vector<ExponentCell> cells;
        run_long("exponent_table", total, progress, [&](const LongRun& control) {
          ExponentRunOptions run;
          run.threads = thread_request;
          run.checkpoint_prefix = prefix;
          run.resume = resume || resume_other_version;
          run.accept_other_version = resume_other_version;
          run.progress = 0;
          run.meter = control.meter;
          run.cancelled = control.cancelled;
          cells = run_exponent_table(config, run);
        });
        if (!prefix.empty())
          for (std::size_t i = 0; i < cells.size(); ++i) CheckpointLog::remove_all(prefix + "." + std::to_string(i));

        nlohmann::json described = nlohmann::json::array();
        for (const auto& c : cells) {
          nlohmann::json one = describe(c.definition);
          one["failed_excluded"] = c.summary.excluded;
          if (c.summary.exponents)
            one["exponents"] = {{"gamma_site", to_json(c.summary.exponents->gamma_site)},
                                {"gamma_centroid", to_json(c.summary.exponents->gamma_centroid)},
                                {"eta", to_json(c.summary.exponents->eta)}};
          if (!c.summary.mle.mean.empty()) one["mle"] = to_json(mle_at_end(c.summary));  // X1(T), as the tool
          one["chain"] = chain_name(c);  // as the exponents tool names it
          described.push_back(one);
        }
        std::string chain_list, kick_list;
        for (const auto& name : chains) chain_list += (chain_list.empty() ? "" : ",") + name;
        for (const auto& name : ic) kick_list += (kick_list.empty() ? "" : ",") + name;
        nlohmann::json meta = metadata_head("exponent_table");
        meta["parameters"] = {{"chains", chain_list},
                              {"F0", config.precompressions},
                              {"ic", kick_list},
                              {"threads", thread_request},
                              {"mpi_ranks", MpiContext::instance().size()}};
        meta["cases"] = described;
        meta["time_step_rule"] = step_rule;
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
        out["metadata"] = to_python(meta);
        return wrap_result("ExponentTable", out);
      },
      py::kw_only(), py::arg("chains") = std::vector<std::string>{"h", "A", "RDM1", "RDM2"},
      py::arg("F0") = std::vector<double>{10, 0.5, 0.1, 0.01, 0},
      py::arg("ic") = std::vector<std::string>{"displacement", "velocity"}, py::arg("N") = 2501, py::arg("xi") = 0.5,
      py::arg("q") = 0.5, py::arg("realizations") = 500, py::arg("seed") = 1, GRANULAR_DYNAMICS_ARGS,
      py::arg("profile_F0") = std::vector<double>{10, 0.1, 0}, py::arg("profile_realizations") = 100,
      py::arg("compare_paper") = false, py::arg("threads") = 0, py::arg("checkpoint") = py::none(),
      py::arg("resume") = false, py::arg("resume_other_version") = false, py::arg("progress") = false,
      GRANULAR_BEYOND_ARGS,
      (std::string("The paper's transport study (the exponents tool): gamma (m2 ~ t^gamma) and eta (P^-1 ~ t^-eta) "
                   "for every chain kind x F0 x kick, each an ensemble of `realizations` (h runs one: it is "
                   "deterministic).\n\n"
                   "    chains: kinds among 'h', 'A', 'RDM1', 'RDM2'; F0: precompressions [N] (0: sonic vacuum); ic: "
                   "kicks\n    N, xi, q, realizations, seed: the chains\n") +
       dynamics_doc + beyond_doc +
       "    profile_F0, profile_realizations: F0s whose E_n(T) is averaged, over how many realizations (None: none)\n"
       "    compare_paper: True (or the path of a table in its format) to compare gamma with the paper's Table I "
       "(z-scores with both error sources)\n"
       "    threads (0: every core); checkpoint: a prefix, case i logs to <prefix>.<i> (removed once done); "
       "resume=True continues an interrupted table (resume_other_version=True: also one another granular version "
       "made); progress: a progress bar\n"
       "Returns a granular.ExponentTable: table (the tool's CSV columns as arrays; with mle also mle, mle_real_err, "
       "mle_sd: the mean X1(T) [1/s], its standard error over realizations, their standard deviation), curves (with "
       "mle also mle, mle_se: <X1(t)> [1/s] and its standard error), profiles, markdown, paper (the comparison, with "
       "compare_paper), metadata (with mle, X1(T) under each case's 'mle'). Releases the GIL; Ctrl-C stops it "
       "resumably "
       "(KeyboardInterrupt).")
          .c_str());
}

}  // namespace granular::python
