// granular.Material, granular.Chain and the ways of making one; the contact law; bead-type
// correlations of one chain. Keywords, defaults and docstrings are in granular/_model.py; here
// the chain makers check their values with the library's rules and build through ChainRecipe.
#include <string>

#include "bindings.hpp"
#include "granular/error.hpp"
#include "granular/model/configuration_file.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/model/correlation.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/model/quasiperiodic.hpp"
#include "granular/model/selected_chain.hpp"

namespace granular::python {
namespace {
/// The chain of a recipe, built and described ("disorder": `name` for a named given chain).
PyChain py_chain(ChainRecipe recipe, std::uint64_t realization, const std::string& name = "") {
  PyChain c;
  static_cast<SelectedChain&>(c) = select_chain(std::move(recipe), realization, {"R1", "beads", "radii"});
  warn(c.warnings);
  c.types = c.recipe.types(realization);
  if (!name.empty()) c.description["disorder"] = name;
  return c;
}

}  // namespace

void bind_model(py::module_& m) {
  m.attr("paper_r1") = paper_r1;
  m.attr("flat_wall") = flat_wall;

  // granular.Material(young, poisson, density): keywords (default: the paper's steel) in granular/_model.py
  config_class(m, "Material", "young poisson density", &Material::young, &Material::poisson, &Material::density);
  m.attr("steel") = steel;

  using Q = Quasiperiodic;  // granular.quasiperiodic's keywords (the tools' --quasi)
  config_class(m, "Quasiperiodic", "modulation phase angle k0 k0_n_per_m", &Q::modulation, &Q::phase, &Q::angle, &Q::k0,
               &Q::k0_n_per_m)
      .def_property("kind", word_getter(&Q::kind), word_setter(&Q::kind, parse_quasi_kind))
      .def_property(
          "ratio", [](const Q& q) { return q.ratio; }, word_setter(&Q::ratio, parse_ratio));

  views(
      py::class_<PyChain>(m, "Chain"), "radius mass inverse_mass contact overlap onsite",
      [](const PyChain& c) -> const Chain& { return c.chain; }, &Chain::radius, &Chain::mass, &Chain::inverse_mass,
      &Chain::contact, &Chain::overlap, &Chain::onsite)
      .def_property_readonly("N", [](const PyChain& c) { return c.chain.size(); })
      .def("__len__", [](const PyChain& c) { return c.chain.size(); })
      .def_property_readonly("F0", [](const PyChain& c) { return c.chain.precompression; })
      .def_property_readonly("types",
                             [](const PyChain& c) { return c.types.empty() ? py::object(py::none()) : to_py(c.types); })
      .def_property_readonly("metadata", [](const PyChain& c) { return to_python(c.description); })
      .def(
          "linear_stiffness", [](const PyChain& c) { return to_numpy(linear_stiffness(c.chain)); },
          "B_k = (3/2) A_k^(2/3) F0^(1/3) [N/m] of the N+1 bonds: the linearized chain");

  // A chain of bead types 1 and 2 filled in granular/_model.py (drawn, or given types), checked by
  // the named chains' rules (ChainParameters) before its walls are read.
  m.def("_typed_chain", [](ChainRecipe r, std::uint64_t realization, const std::string& walls, const std::string& name) {
    const GivenTypes* given = r.as<GivenTypes>();
    const std::size_t n = given ? std::max<std::size_t>(given->types.size(), 2) : r.N;
    const double q = given ? 0.5 : r.draw().q;
    validate(ChainParameters{.N = n, .q = q, .xi = r.xi(), .F0 = r.F0, .R1 = r.R1, .material = r.material});
    if (given && given->types.size() < 2)
      bad_value("types", ": " + std::to_string(given->types.size()) + " beads; a chain needs at least 2");
    r.walls = parse_wall_shape(walls);
    return py_chain(r, realization, name);
  });
  // A chain of a recipe filled in granular/_model.py (given radii, a quasiperiodic chain).
  m.def("_chain", [](const ChainRecipe& recipe, std::uint64_t realization) { return py_chain(recipe, realization); });
  m.def("_configuration", [](const std::string& disorder, double q, std::size_t N, std::uint64_t seed,
                             std::uint64_t realization) {  // sizes checked in granular/_model.py
    validate_probability(q);
    return to_numpy(realization_configuration(disorder_of(disorder), q, N, seed, realization));
  });
  m.def("_read_types", [](const std::string& path) { return to_numpy(read_configuration_file(path)); });
  m.def("_read_radii", [](const std::string& path) { return to_numpy(read_radii_file(path)); });

  // --- the contact law (checked in granular/_model.py) --------------------------------------------
  m.def("_hertz_coefficient",
        [](double ra, double rb, const Material& a, const Material& b) { return hertz_coefficient(a, ra, b, rb); });
  m.def("_static_overlap", py::overload_cast<double, double>(&static_overlap));
  m.def("_linear_stiffness", py::overload_cast<double, double>(&linear_stiffness));
  m.def("_nonlinearity_ratio", &nonlinearity_ratio);
  using F = FpuCoefficients;
  readonly(py::class_<F>(m, "FpuCoefficients"), "b1 b2 b3", &F::b1, &F::b2, &F::b3)
      .def_property_readonly("modulational_discriminant", &FpuCoefficients::modulational_discriminant);
  m.def("_fpu_coefficients", [](double contact, double F0) { return fpu_coefficients(contact, F0); });

  // --- correlations of one chain -----------------------------------------------------------------
  m.def("_cyclic_correlation", [](const Configuration& types, std::size_t max_distance) {
    return to_numpy(cyclic_correlation(types, max_distance));  // both checked in granular/_model.py
  });
  m.def("_correlation_theory", [](const std::string& disorder, double q, long long distance) {
    validate_probability(q);  // a distance array is taken apart in granular/_model.py
    return correlation_theory(disorder_of(disorder), q, checked_size(distance, "distance"));
  });
}

}  // namespace granular::python
