// The extension module granular._core. The package granular (python/granular/__init__.py) is its
// face: the keyword functions, docstrings and result classes (granular/_model.py, _linear.py,
// _studies.py, _dynamics.py, _observers.py), results, progress bar, figures.
#include "bindings.hpp"
#include "granular/code_identity.hpp"
#include "granular/parallel/mpi_context.hpp"

PYBIND11_MODULE(_core, m) {
  using namespace granular::python;
  m.doc() = "The C++ core of granular: chains, spectra, studies and dynamics (see the package granular).";
  m.attr("__version__") = granular::code_version();
  // Decide on MPI here, on the importing (main) thread: it starts only under mpirun.
  granular::MpiContext::instance();
  bind_errors(m);
  bind_model(m);
  bind_linear(m);
  bind_studies(m);
  bind_dynamics(m);
  bind_observers(m);
  bind_breathers(m);
  bind_crystal(m);
  bind_klein_gordon(m);
}
