// The linear chain under granular.spectrum, SpectrumSolver, DynamicalMatrix and band_edges
// (keywords, defaults, docstrings and the Spectrum result in granular/_linear.py): the dynamical
// matrix, one solve per call (every mode / the K nearest a frequency / a window, by every
// method) with the GIL released, the result's arrays as read-only views. Frequencies in kHz.
#include <cmath>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>

#include "bindings.hpp"
#include "granular/error.hpp"
#include "granular/files/spectrum_file.hpp"
#include "granular/linear/band_edges.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_selection_choices.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/linear/spectrum_parameters.hpp"
#include "granular/linear/sym_tridiagonal.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/model/plausibility.hpp"

namespace granular::python {
namespace {

/// ARPACK keeps state in Fortran SAVE variables and SLEPc talks MPI: one call at a time per process.
std::mutex& serial_solvers() {
  static std::mutex m;
  return m;
}

/// One solve of `matrix`, or of the dynamical matrix of `chain` built into `owned`, with the GIL
/// released; ARPACK and SLEPc one at a time.
Spectrum solve(SpectrumSolver& solver, const PyChain* chain, const DynamicalMatrix*& matrix, DynamicalMatrix& owned,
               const ModeSelection& selection) {
  py::gil_scoped_release release;
  if (chain) matrix = &(owned = dynamical_matrix(chain->chain));
  validate(selection, matrix->size());
  const SpectrumMethod method = solver.config().method;
  std::unique_lock lock(serial_solvers(), std::defer_lock);
  if (method == SpectrumMethod::arpack || method == SpectrumMethod::slepc) lock.lock();
  return solver.solve(*matrix, selection);
}

}  // namespace

void bind_linear(py::module_& m) {
  // What a granular.Spectrum (granular/_linear.py) takes its arrays from: read-only views of the
  // result (eigenvectors N per mode, one after the other), mode numbers as signed integers.
  using S = Spectrum;
  readonly(views(py::class_<S>(m, "_Modes"), "omega2 freq_khz ipr residual vectors", std::identity{}, &S::omega2,
                 &S::freq_khz, &S::ipr, &S::residual, &S::vectors),
           "mode clustered N", &S::mode, &S::clustered, &S::beads)
      .def_property_readonly("info", [](const S& s) {
        const SpectrumInfo& i = s.info;
        return fields("method fallbacks restarts candidates max_residual clusters", i.method, i.fallbacks, i.restarts,
                      i.candidates, i.max_residual, i.clusters);
      });
  using D = DynamicalMatrix;  // checked in granular/_linear.py
  views(py::class_<D>(m, "DynamicalMatrix"), "diagonal off_diagonal inverse_sqrt_mass", std::identity{}, &D::diagonal,
        &D::off_diagonal, &D::inverse_sqrt_mass)
      .def(py::init([](std::vector<double> diagonal, std::vector<double> off_diagonal, std::vector<double> isqm) {
        return D{{std::move(diagonal), std::move(off_diagonal)}, std::move(isqm)};
      }))
      .def_property_readonly("N", &DynamicalMatrix::size)
      .def("__len__", &DynamicalMatrix::size)
      .def("__repr__",
           [](const DynamicalMatrix& d) { return "<granular.DynamicalMatrix N=" + std::to_string(d.size()) + ">"; });

  m.def("_dynamical_matrix", [](const PyChain& c) { return dynamical_matrix(c.chain); });
  m.def("_frequency_khz", [](py::array_t<double> omega2) { return py::vectorize(frequency_khz)(omega2); });
  m.def("_omega2_of_khz", [](py::array_t<double> khz) { return py::vectorize(omega_squared_of_khz)(khz); });

  // What granular/_linear.py fills from the keywords: the selection and the solver's config.
  py::class_<ModeSelection>(m, "ModeSelection").def(py::init<>());
  table_class(m, "ModeSelectionChoices", mode_selection_parameters())  // near, count; window (lo, hi): no field
      .def_readwrite("window", &ModeSelectionChoices::window);
  m.def("_choose_modes", py::overload_cast<const ModeSelectionChoices&>(&choose_modes));  // the tools' rule
  table_class(m, "SpectrumConfig", spectrum_parameters());

  // granular.spectrum and granular.SpectrumSolver: one solve of a Chain or of a DynamicalMatrix
  // (the other None: granular/_linear.py); `check_units` warns of a frequency keyword beyond the
  // chain's highest frequency (Hz given as kHz). One call at a time per solver (its workspace):
  // granular/_linear.py holds a lock around it.
  py::class_<SpectrumSolver>(m, "_SpectrumSolver")
      .def(py::init<const SpectrumConfig&>())
      .def("_solve", [](SpectrumSolver& solver, const PyChain* chain, const DynamicalMatrix* matrix,
                        const ModeSelection& selection, bool check_units) {
        const SpectrumRequest q{selection, solver.config()};
        validate(q.config, q.selection);
        if (check_units && q.selection.kind != ModeSelection::Kind::all) {
          const bool by_near = q.selection.kind == ModeSelection::Kind::nearest;
          const double top = chain ? highest_frequency_bound_khz(chain->recipe)
                                   : frequency_khz(std::max(0.0, gershgorin_bounds(*matrix).second));
          warn({frequency_warning(by_near ? "near" : "window", by_near ? q.selection.near_khz : q.selection.lo_khz,
                                  top)});
        }
        DynamicalMatrix owned;
        Spectrum r = solve(solver, chain, matrix, owned, q.selection);
        // The spectrum tool's JSON for this result (the library's describe_spectrum, as the tool writes it).
        const py::object meta = metadata("spectrum", describe_spectrum(r, q, chain ? chain->description : nullptr,
                                                                       chain ? chain->recipe.material : steel));
        return py::make_tuple(std::move(r), to_numpy(matrix->inverse_sqrt_mass), meta);
      });

  m.def("_band_edges", [](double xi, double F0, double R1, const Material& material) {
    const BandEdges e = band_edges(material, R1, xi, F0);
    return py::make_tuple(e.f1 * 1e-3, e.f2 * 1e-3, e.fb1 * 1e-3, e.fb2 * 1e-3, e.fb3 * 1e-3);
  });
}

}  // namespace granular::python
