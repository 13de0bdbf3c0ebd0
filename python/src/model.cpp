// granular.Material, granular.Chain and the ways of making one; the contact law; bead-type
// correlations of one chain. Keywords, defaults and docstrings are in granular/_model.py; here
// the chain makers check their values with the library's rules and build through ChainRecipe.
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "granular/error.hpp"
#include "granular/model/configuration_file.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/model/correlation.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/model/plausibility.hpp"
#include "granular/model/quasiperiodic.hpp"
#include "granular/number_format.hpp"

namespace granular::python {
namespace {

py::object chain_types(const PyChain& c) {
  if (c.types.empty()) return py::none();
  std::vector<std::uint8_t> copy(c.types.begin(), c.types.end());
  return to_numpy(std::move(copy));
}

}  // namespace

PyChain py_chain(ChainRecipe recipe, std::uint64_t realization, const std::string& name) {
  validate(recipe);
  warn(radius_warnings(recipe, {"R1", "beads", "radii"}));
  PyChain c;
  c.chain = recipe.chain(realization);
  c.types = recipe.types(realization);
  c.material = recipe.material;
  c.description = describe(recipe, realization);
  if (!name.empty()) c.description["disorder"] = name;
  c.recipe = std::move(recipe);
  c.realization = realization;
  return c;
}

void bind_model(py::module_& m) {
  m.attr("paper_r1") = paper_r1;
  m.attr("flat_wall") = flat_wall;

  py::class_<Material>(m, "Material")
      .def(py::init([](double young, double poisson, double density) {
             return Material{young, poisson, density};
           }),
           py::arg("young") = steel.young, py::arg("poisson") = steel.poisson, py::arg("density") = steel.density)
      .def_readwrite("young", &Material::young)
      .def_readwrite("poisson", &Material::poisson)
      .def_readwrite("density", &Material::density)
      .def("__repr__", [](const Material& x) {
        return "Material(young=" + format_number(x.young) + ", poisson=" + format_number(x.poisson) +
               ", density=" + format_number(x.density) + ")";
      });
  m.attr("steel") = steel;

  using Q = Quasiperiodic;  // granular.quasiperiodic's keywords (the tools' --quasi)
  config_class(m, "Quasiperiodic", "modulation phase angle k0", &Q::modulation, &Q::phase, &Q::angle, &Q::k0)
      .def_property(
          "kind", [](const Q& q) { return to_string(q.kind); },
          [](Q& q, const std::string& word) { q.kind = parse_quasi_kind(word); })
      .def_property(
          "ratio", [](const Q& q) { return q.ratio; },
          [](Q& q, const std::string& text) { q.ratio = parse_ratio(text); });

  py::class_<PyChain>(m, "Chain")
      .def_property_readonly("N", [](const PyChain& c) { return c.chain.size(); })
      .def("__len__", [](const PyChain& c) { return c.chain.size(); })
      .def_property_readonly("radius", viewer<PyChain>([](const PyChain& c) -> auto& { return c.chain.radius; }))
      .def_property_readonly("mass", viewer<PyChain>([](const PyChain& c) -> auto& { return c.chain.mass; }))
      .def_property_readonly("inverse_mass",
                             viewer<PyChain>([](const PyChain& c) -> auto& { return c.chain.inverse_mass; }))
      .def_property_readonly("contact", viewer<PyChain>([](const PyChain& c) -> auto& { return c.chain.contact; }))
      .def_property_readonly("overlap", viewer<PyChain>([](const PyChain& c) -> auto& { return c.chain.overlap; }))
      .def_property_readonly("onsite", viewer<PyChain>([](const PyChain& c) -> auto& { return c.chain.onsite; }))
      .def_property_readonly("F0", [](const PyChain& c) { return c.chain.precompression; })
      .def_property_readonly("types", &chain_types)
      .def_property_readonly("metadata", [](const PyChain& c) { return to_python(c.description); })
      .def(
          "linear_stiffness", [](const PyChain& c) { return to_numpy(linear_stiffness(c.chain)); },
          "B_k = (3/2) A_k^(2/3) F0^(1/3) [N/m] of the N+1 bonds: the linearized chain")
      .def("__repr__", [](const PyChain& c) {
        std::string what = c.description.contains("disorder") ? c.description["disorder"].get<std::string>()
                                                              : (c.types.empty() ? "radii" : "types");
        return "<granular.Chain " + what + ", N=" + std::to_string(c.chain.size()) +
               ", F0=" + format_number(c.chain.precompression) + " N>";
      });

  // A chain of bead types 1 and 2 filled in granular/_model.py (drawn, or given types), checked by
  // the named chains' rules (ChainParameters) before its walls are read.
  m.def("_typed_chain", [](ChainRecipe r, std::uint64_t realization, const std::string& walls, const std::string& name) {
    const std::size_t n = r.given_types ? std::max<std::size_t>(r.given_types->size(), 2) : r.N;
    validate(ChainParameters{.N = n, .q = r.q, .xi = r.xi, .F0 = r.F0, .R1 = r.R1, .material = r.material});
    if (r.given_types && r.given_types->size() < 2)
      bad_value("types", ": " + std::to_string(r.given_types->size()) + " beads; a chain needs at least 2");
    r.walls = parse_wall_shape(walls);
    return py_chain(r, realization, name);
  });
  m.def("_types", &types_vector);
  // A chain of a recipe filled in granular/_model.py (given radii, a quasiperiodic chain).
  m.def("_chain", [](const ChainRecipe& recipe, std::uint64_t realization) { return py_chain(recipe, realization); });
  m.def("_configuration", [](const std::string& disorder, double q, long long N, long long seed, long long realization) {
    validate_probability(q);
    auto t = realization_configuration(disorder_of(disorder), q, checked_size(N, "N", 2, 100000000),
                                       checked_size(seed, "seed"), checked_size(realization, "realization"));
    return to_numpy(std::vector<std::uint8_t>(t.begin(), t.end()));
  });
  m.def("_read_types", [](const std::string& path) {
    auto t = read_configuration_file(path);
    return to_numpy(std::vector<std::uint8_t>(t.begin(), t.end()));
  });
  m.def("_read_radii", [](const std::string& path) { return to_numpy(read_radii_file(path)); });

  // --- the contact law (checked in granular/_model.py) --------------------------------------------
  m.def("_hertz_coefficient",
        [](double ra, double rb, const Material& a, const Material& b) { return hertz_coefficient(a, ra, b, rb); });
  m.def("_static_overlap", py::overload_cast<double, double>(&static_overlap));
  m.def("_linear_stiffness", py::overload_cast<double, double>(&linear_stiffness));
  m.def("_nonlinearity_ratio", &nonlinearity_ratio);
  py::class_<FpuCoefficients>(m, "FpuCoefficients")
      .def_readonly("b1", &FpuCoefficients::b1)
      .def_readonly("b2", &FpuCoefficients::b2)
      .def_readonly("b3", &FpuCoefficients::b3)
      .def_property_readonly("modulational_discriminant", &FpuCoefficients::modulational_discriminant)
      .def("__repr__", [](const FpuCoefficients& f) {
        return "FpuCoefficients(b1=" + format_number(f.b1) + ", b2=" + format_number(f.b2) +
               ", b3=" + format_number(f.b3) + ")";
      });
  m.def("_fpu_coefficients", [](double contact, double F0) { return fpu_coefficients(contact, F0); });

  // --- correlations of one chain -----------------------------------------------------------------
  m.def("_cyclic_correlation", [](const py::object& types, long long max_distance) {
    Configuration t = py::isinstance<PyChain>(types) ? types.cast<const PyChain&>().types : types_vector(types, "types");
    if (t.empty()) bad_value("types", ": the chain was built from radii and has no bead types");
    const std::size_t d = checked_size(max_distance, "max_distance", 0, static_cast<long long>(t.size()) - 1);
    return to_numpy(cyclic_correlation(t, d));
  });
  m.def("_correlation_theory", [](const std::string& disorder, double q, const py::object& distance) -> py::object {
    validate_probability(q);
    const Disorder kind = disorder_of(disorder);
    if (py::isinstance<py::int_>(distance))
      return py::float_(correlation_theory(kind, q, checked_size(distance.cast<long long>(), "distance")));
    std::vector<double> d = double_vector(distance, "distance");
    std::vector<double> out(d.size());
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (d[i] < 0 || d[i] != std::floor(d[i]))
        bad_value("distance",
                  ": entry " + std::to_string(i) + " is " + format_number(d[i]) + " (must be a whole number >= 0)");
      out[i] = correlation_theory(kind, q, static_cast<std::size_t>(d[i]));
    }
    return to_numpy(std::move(out));
  });
}

}  // namespace granular::python
