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

}  // namespace

void bind_observers(py::module_& m) {
  readonly(py::class_<State>(m, "State"), "u v", &State::u, &State::v)  // checked in granular/_observers.py
      .def(py::init([](std::vector<double> u, std::vector<double> v) {
        State s;
        s.u = std::move(u), s.v = std::move(v);
        return s;
      }));
  // Kicks and observers take their settings checked in granular/_observers.py (sites as 0-based indices).
  m.def("_displacement_kick",
        [](const PyChain& c, std::size_t site, double alpha) { return displacement_kick(c.chain, site, alpha); });
  m.def("_velocity_kick",
        [](const PyChain& c, std::size_t site, double beta) { return velocity_kick(c.chain, site, beta); });

  readonly(py::class_<RunPlan>(m, "RunPlan"), "beads total_steps time_step duration", &RunPlan::beads,
           &RunPlan::total_steps, &RunPlan::time_step, &RunPlan::duration);
  using S = SnapshotCopy;
  readonly(py::class_<S>(m, "Snapshot"), "step t initial_energy u v energy", &S::step, &S::t, &S::initial_energy, &S::u,
           &S::v, &S::energy);

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

  config_class(m, "DenseGrid", "begin end step", &DenseGrid::begin, &DenseGrid::end, &DenseGrid::step);
  using E = EnergySpreadObserver;
  config_class(m, "EnergySpreadSettings", "samples dense site max_energy_error stop_on_energy_error wall_warning",
               &E::Settings::samples, &E::Settings::dense, &E::Settings::site, &E::Settings::max_energy_error,
               &E::Settings::stop_on_energy_error, &E::Settings::wall_warning)
      .def_property("sampling", word_getter(&E::Settings::sampling),
                    word_setter(&E::Settings::sampling, parse_sampling));
  readonly(py::class_<E, Observer>(m, "EnergySpread").def(py::init<const E::Settings&>()),
           "t m2 m2_centroid ipr energy_error max_energy_error wall_energy energy_guard_time", &E::t, &E::m2,
           &E::m2_centroid, &E::ipr, &E::energy_error, &E::max_energy_error, &E::wall_energy, &E::energy_guard_time)
      .def_property_readonly("reached_walls", &E::reached_walls);  // energy_guard_time's None: _observers.py

  config_class(m, "ForcesSettings", "sites samples", &ForceObserver::Settings::sites, &ForceObserver::Settings::samples);
  readonly(py::class_<ForceObserver, Observer>(m, "Forces").def(py::init<ForceObserver::Settings>()), "t",
           &ForceObserver::t)
      .def_property_readonly("force", [](const ForceObserver& o) {
        std::vector<double> values;
        for (const auto& series : o.forces) values.insert(values.end(), series.begin(), series.end());
        return to_numpy(std::move(values)).reshape({o.forces.size(), o.t.size()});  // sites × times
      });

  using M = EnergyMapObserver;
  config_class(m, "EnergyMapSettings", "samples stride", &M::Settings::samples, &M::Settings::stride);
  readonly(py::class_<M, Observer>(m, "EnergyMap").def(py::init<const M::Settings&>()), "t", &M::t)
      .def_property_readonly("energy", [](const M& o) {
        return to_numpy(o.energy).reshape({o.t.size(), o.columns});  // times × columns
      });

  using D = SpectralDensityObserver;
  config_class(m, "SpectralDensitySettings", "samples", &D::Settings::samples)
      .def_property("of", word_getter(&D::Settings::source), word_setter(&D::Settings::source, parse_spectrum_source));
  readonly(py::class_<D, Observer>(m, "SpectralDensity").def(py::init<const D::Settings&>()), "freq_khz g",
           &D::freq_khz, &D::density);

  readonly(py::class_<FinalStateObserver, Observer>(m, "FinalState").def(py::init<>()), "energy force",
           &FinalStateObserver::energy, &FinalStateObserver::force)
      .def_property_readonly("u", [](const FinalStateObserver& o) { return to_numpy(o.state.u); })
      .def_property_readonly("v", [](const FinalStateObserver& o) { return to_numpy(o.state.v); });

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
    return fields("initial_energy steps bond_updates window seconds", info.initial_energy, info.steps,
                  info.bond_updates, py::make_tuple(info.window_begin, info.window_end), info.seconds);
  });
}

}  // namespace granular::python
