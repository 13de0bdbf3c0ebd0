// The dynamics as the library has it: an initial state, granular.spread() — which owns time and
// the integrator — and observers that measure the run (dynamics/observer.hpp, observers.hpp).
// Docstrings, and the keywords of spread() and the kicks, are in granular/_observers.py.
// The built-in observers keep their results as NumPy arrays; a Python class deriving from
// granular.Observer (schedule, observe, finish) is called like them, with the GIL taken for it.
// Beads are 0-based here, as in granular.Chain's arrays (the tools and granular.spreading count
// from 1).
#include <string>
#include <vector>

#include "bindings.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observers.hpp"
#include "granular/dynamics/spread.hpp"
#include "granular/error.hpp"

namespace granular::python {
namespace {
using namespace py::literals;

/// What Python receives for a Snapshot: a copy of the chain at that time. The library's Snapshot
/// is a view of the integrator's state, which moves on after the call; an observer that keeps
/// what it was given (frames.append(now)) must keep that time's state, not a later one.
struct SnapshotCopy {
  std::uint64_t step = 0;
  double t = 0;
  std::vector<double> u, v, energy;
  double initial_energy = 0;
};

std::vector<double> copy(std::span<const double> x) { return {x.begin(), x.end()}; }

/// A Python subclass of granular.Observer.
class PyObserver : public Observer {
 public:
  std::vector<std::uint64_t> schedule(const RunPlan& plan) override {
    PYBIND11_OVERRIDE_PURE(std::vector<std::uint64_t>, Observer, schedule, plan);
  }
  void observe(const Snapshot& now) override { call("observe", now, true); }
  void finish(const Snapshot& at_T) override { call("finish", at_T, false); }

 private:
  void call(const char* name, const Snapshot& snapshot, bool required) {
    py::gil_scoped_acquire gil;
    const py::function method = py::get_override(static_cast<const Observer*>(this), name);
    if (method) {
      method(SnapshotCopy{snapshot.step, snapshot.t, copy(snapshot.u), copy(snapshot.v), copy(snapshot.energy()),
                          snapshot.initial_energy()});
    } else if (required) {
      throw InvalidInput(std::string("observer: a granular.Observer must define ") + name + "()");
    }
  }
};

std::size_t site_of(const py::object& site, const char* keyword) {
  const long long s = site.cast<long long>();
  if (s < 0) bad_value(keyword, " " + std::to_string(s) + ": a bead index (0-based) is >= 0");
  return static_cast<std::size_t>(s);
}

}  // namespace

void bind_observers(py::module_& m) {
  py::class_<State>(m, "State")
      .def(py::init([](const py::object& u, const py::object& v) {
             State s;
             s.u = double_vector(u, "u");
             s.v = double_vector(v, "v");
             if (s.u.size() != s.v.size()) bad_value("v", ": needs as many entries as u");
             return s;
           }),
           py::arg("u"), py::arg("v"))
      .def_property_readonly("u", [](const State& s) { return to_numpy(s.u); })
      .def_property_readonly("v", [](const State& s) { return to_numpy(s.v); });
  m.def("_displacement_kick", [](const PyChain& chain, const py::object& site, double alpha) {
    return displacement_kick(chain.chain, site_of(site, "site"), alpha);
  });
  m.def("_velocity_kick", [](const PyChain& chain, const py::object& site, double beta) {
    return velocity_kick(chain.chain, site_of(site, "site"), beta);
  });

  py::class_<RunPlan>(m, "RunPlan")
      .def_readonly("beads", &RunPlan::beads)
      .def_readonly("total_steps", &RunPlan::total_steps)
      .def_readonly("time_step", &RunPlan::time_step)
      .def_readonly("duration", &RunPlan::duration);
  py::class_<SnapshotCopy>(m, "Snapshot")
      .def_readonly("step", &SnapshotCopy::step)
      .def_readonly("t", &SnapshotCopy::t)
      .def_property_readonly("u", [](const SnapshotCopy& s) { return to_numpy(s.u); })
      .def_property_readonly("v", [](const SnapshotCopy& s) { return to_numpy(s.v); })
      .def_property_readonly("energy", [](const SnapshotCopy& s) { return to_numpy(s.energy); })
      .def_readonly("initial_energy", &SnapshotCopy::initial_energy);

  py::class_<Observer, PyObserver>(m, "Observer")
      .def(py::init<>())
      .def("schedule", &Observer::schedule, py::arg("plan"))
      // What super().observe/finish(snapshot) reach from a subclass: the base's behaviour.
      .def(
          "observe",
          [](Observer&, const SnapshotCopy&) {
            throw InvalidInput("observer: a granular.Observer must define observe()");
          },
          py::arg("snapshot"))
      .def(
          "finish", [](Observer&, const SnapshotCopy&) {}, py::arg("snapshot"));

  py::class_<EnergySpreadObserver, Observer>(m, "EnergySpread")
      .def(py::init([](long long samples, const std::string& sampling, const py::object& site, const py::object& fit,
                       double fit_step, double max_energy_error, const std::string& energy_guard, double wall_warning) {
             EnergySpreadObserver::Settings s;
             s.samples = checked_size(samples, "samples", 2);
             s.sampling = parse_sampling(sampling);
             if (!site.is_none()) s.site = site_of(site, "site");
             if (!fit.is_none()) {
               const std::vector<double> window = double_vector(fit, "fit");
               if (window.size() != 2) bad_value("fit", ": expected (start, stop) [s]");
               s.dense = {window[0], window[1], fit_step};
             }
             s.max_energy_error = finite(max_energy_error, "max_energy_error");
             if (energy_guard != "stop" && energy_guard != "warn")
               bad_value("energy_guard", " '" + energy_guard + "': stop or warn");
             s.stop_on_energy_error = energy_guard == "stop";
             s.wall_warning = wall_warning;
             return EnergySpreadObserver(s);
           }),
           py::kw_only(), py::arg("samples") = 100, py::arg("sampling") = "log", py::arg("site") = py::none(),
           py::arg("fit") = py::none(), py::arg("fit_step") = 1e-5, py::arg("max_energy_error") = 1e-3,
           py::arg("energy_guard") = "stop", py::arg("wall_warning") = 1e-10)
      .def_property_readonly("t", [](const EnergySpreadObserver& o) { return to_numpy(o.t); })
      .def_property_readonly("m2", [](const EnergySpreadObserver& o) { return to_numpy(o.m2); })
      .def_property_readonly("m2_centroid", [](const EnergySpreadObserver& o) { return to_numpy(o.m2_centroid); })
      .def_property_readonly("ipr", [](const EnergySpreadObserver& o) { return to_numpy(o.ipr); })
      .def_property_readonly("energy_error", [](const EnergySpreadObserver& o) { return to_numpy(o.energy_error); })
      .def_readonly("max_energy_error", &EnergySpreadObserver::max_energy_error)
      .def_readonly("wall_energy", &EnergySpreadObserver::wall_energy)
      .def_property_readonly("reached_walls", &EnergySpreadObserver::reached_walls)
      .def_property_readonly("energy_guard_time", [](const EnergySpreadObserver& o) {
        return o.energy_guard_time < 0 ? py::object(py::none()) : py::float_(o.energy_guard_time);
      });

  py::class_<ForceObserver, Observer>(m, "Forces")
      .def(py::init([](const py::object& at, long long samples) {
             ForceObserver::Settings s;
             for (const py::handle& site : at)
               s.sites.push_back(site_of(py::reinterpret_borrow<py::object>(site), "at"));
             s.samples = checked_size(samples, "samples", 2);
             return ForceObserver(s);
           }),
           py::arg("at"), py::kw_only(), py::arg("samples") = 1000)
      .def_property_readonly("t", [](const ForceObserver& o) { return to_numpy(o.t); })
      .def_property_readonly("force", [](const ForceObserver& o) {
        std::vector<double> values;
        for (const auto& series : o.forces) values.insert(values.end(), series.begin(), series.end());
        return to_numpy_2d(std::move(values), o.forces.size(), o.t.size());
      });

  py::class_<EnergyMapObserver, Observer>(m, "EnergyMap")
      .def(py::init([](long long samples, long long stride) {
             return EnergyMapObserver({checked_size(samples, "samples", 2), checked_size(stride, "stride", 1)});
           }),
           py::kw_only(), py::arg("samples") = 500, py::arg("stride") = 1)
      .def_property_readonly("t", [](const EnergyMapObserver& o) { return to_numpy(o.t); })
      .def_property_readonly("energy", [](const EnergyMapObserver& o) {
        return to_numpy_2d(std::vector<double>(o.energy), o.t.size(), o.columns);
      });

  py::class_<SpectralDensityObserver, Observer>(m, "SpectralDensity")
      .def(py::init([](long long samples, const std::string& of) {
             return SpectralDensityObserver({checked_size(samples, "samples", 2), parse_spectrum_source(of)});
           }),
           py::kw_only(), py::arg("samples") = 2000, py::arg("of") = "displacement")
      .def_property_readonly("freq_khz", [](const SpectralDensityObserver& o) { return to_numpy(o.freq_khz); })
      .def_property_readonly("g", [](const SpectralDensityObserver& o) { return to_numpy(o.density); });

  py::class_<FinalStateObserver, Observer>(m, "FinalState")
      .def(py::init<>())
      .def_property_readonly("u", [](const FinalStateObserver& o) { return to_numpy(o.state.u); })
      .def_property_readonly("v", [](const FinalStateObserver& o) { return to_numpy(o.state.v); })
      .def_property_readonly("energy", [](const FinalStateObserver& o) { return to_numpy(o.energy); })
      .def_property_readonly("force", [](const FinalStateObserver& o) { return to_numpy(o.force); });

  m.def("_spread", [](const PyChain& chain, const State& initial, const py::list& observers, double T, double dt,
                      const std::string& integrator, const std::string& force_law, bool active_window,
                      double window_threshold, double reference_max_step) {
    IntegrationConfig config;
    config.duration = T;
    config.time_step = dt;
    config.integrator = parse_integrator(integrator);
    config.integrator.tolerance.max_step = finite(reference_max_step, "reference_max_step");
    config.force_law = parse_force_law(force_law);
    config.window.enabled = active_window;
    config.window.threshold = window_threshold;
    std::vector<Observer*> list;
    for (const py::handle& o : observers) list.push_back(o.cast<Observer*>());
    RunInfo info;
    {
      py::gil_scoped_release release;  // Python observers take it back when called
      info = spread(chain.chain, initial, config, list);
    }
    return py::dict("initial_energy"_a = info.initial_energy, "steps"_a = info.steps,
                    "bond_updates"_a = info.bond_updates,
                    "window"_a = py::make_tuple(info.window_begin, info.window_end), "seconds"_a = info.seconds);
  });
}

}  // namespace granular::python
