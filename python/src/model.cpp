// granular.Material, granular.Chain and the ways of making one; the contact law; bead-type
// correlations of one chain. Keywords and units as the tools' options: N, q, xi, seed,
// realization, F0 [N], R1 [m].
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "bindings.hpp"
#include "granular/error.hpp"
#include "granular/model/configuration_file.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/model/correlation.hpp"
#include "granular/model/named_chains.hpp"
#include "granular/model/plausibility.hpp"
#include "granular/number_format.hpp"

namespace granular::python {
namespace {

ChainParameters chain_parameters(long long N, double q, double xi, long long seed, long long realization, double F0,
                                 double R1, const Material& material) {
  ChainParameters p;
  p.N = checked_size(N, "N", 2, 100000000);
  p.q = q;
  p.xi = xi;
  p.seed = checked_size(seed, "seed");
  p.realization = checked_size(realization, "realization");
  p.F0 = F0;
  p.R1 = R1;
  p.material = material;
  validate(p);
  return p;
}

ChainRecipe recipe_of(const ChainParameters& p) {
  return {.q = p.q, .xi = p.xi, .R1 = p.R1, .N = p.N, .F0 = p.F0, .material = p.material, .seed = p.seed};
}

PyChain random_py_chain(Disorder kind, const ChainParameters& p) {
  ChainRecipe r = recipe_of(p);
  r.disorder = kind;
  return py_chain(r, p.realization);
}

const char* chain_keywords_doc =
    "\n\nKeywords (as the tools' options):\n"
    "    N: beads (>= 2)\n"
    "    q: probability of a type-1 bead (A), of dimer 11 (RDM1) or of dimer 12 (RDM2), in [0, 1]\n"
    "    xi: size ratio R2/R1 in (0, 1]\n"
    "    seed, realization: realization r of seed s is always the same chain (any machine, any thread)\n"
    "    F0: static precompression [N], >= 0 (0: the sonic vacuum, no linear spectrum)\n"
    "    R1: radius of type-1 beads [m]; type 2 has xi*R1\n"
    "    material: granular.Material of beads and walls (default granular.steel)\n"
    "Returns a granular.Chain. Raises ValueError naming the keyword when a value is out of range.";

void bind_random(py::module_& m, const char* name, Disorder kind, const std::string& doc) {
  m.def(
      name,
      [kind](long long N, double q, double xi, long long seed, long long realization, double F0, double R1,
             const Material& material) {
        return random_py_chain(kind, chain_parameters(N, q, xi, seed, realization, F0, R1, material));
      },
      py::arg("N") = 100, py::arg("q") = 0.5, py::arg("xi") = 0.5, py::arg("seed") = 1, py::arg("realization") = 0,
      py::arg("F0") = 10.0, py::arg("R1") = paper_r1, py::arg("material") = steel, (doc + chain_keywords_doc).c_str());
}

/// OSError (FileNotFoundError, PermissionError, …) naming the file when it cannot be opened: the
/// library reports an unreadable input file as bad input (the tools' exit code 2), Python as a file error.
void check_readable(const std::string& path) {
  errno = 0;
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    errno = EISDIR;
  } else if (std::FILE* f = std::fopen(path.c_str(), "r")) {
    std::fclose(f);
    return;
  }
  PyErr_SetFromErrnoWithFilename(PyExc_OSError, path.c_str());
  throw py::error_already_set();
}

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

  py::class_<Material>(m, "Material", "Elastic material of beads and walls, SI units.")
      .def(py::init([](double young, double poisson, double density) {
             return Material{young, poisson, density};
           }),
           py::arg("young") = steel.young, py::arg("poisson") = steel.poisson, py::arg("density") = steel.density,
           "young: Young modulus E [Pa]; poisson: Poisson ratio nu [-]; density: rho [kg/m^3]. Defaults: the paper's "
           "stainless steel.")
      .def_readwrite("young", &Material::young, "Young modulus E [Pa]")
      .def_readwrite("poisson", &Material::poisson, "Poisson ratio nu [-]")
      .def_readwrite("density", &Material::density, "mass density rho [kg/m^3]")
      .def("__repr__", [](const Material& x) {
        return "Material(young=" + format_number(x.young) + ", poisson=" + format_number(x.poisson) +
               ", density=" + format_number(x.density) + ")";
      });
  m.attr("steel") = steel;

  py::class_<PyChain>(m, "Chain",
                      "A chain of N beads between two flat walls under a static precompression F0 (SPEC §1).\n\n"
                      "Beads are indexed 0..N-1 here (bead n+1 of the tools' files); bonds 0..N, bond k joining "
                      "bead k-1 and bead k (bond 0 and bond N touch the walls). The arrays are read-only views.\n"
                      "Make one with granular.anderson/rdm1/rdm2/homogeneous/diatomic, random_chain, from_types "
                      "or from_radii.")
      .def_property_readonly(
          "N", [](const PyChain& c) { return c.chain.size(); }, "number of beads")
      .def("__len__", [](const PyChain& c) { return c.chain.size(); })
      .def_property_readonly(
          "radius", [](py::object self) { return view(self.cast<const PyChain&>().chain.radius, self); },
          "bead radii R_n [m], N entries")
      .def_property_readonly(
          "mass", [](py::object self) { return view(self.cast<const PyChain&>().chain.mass, self); },
          "bead masses m_n = rho (4/3) pi R_n^3 [kg], N entries")
      .def_property_readonly(
          "inverse_mass", [](py::object self) { return view(self.cast<const PyChain&>().chain.inverse_mass, self); },
          "1/m_n [1/kg], N entries")
      .def_property_readonly(
          "contact", [](py::object self) { return view(self.cast<const PyChain&>().chain.contact, self); },
          "Hertz contact coefficients A_k [N/m^(3/2)] of the N+1 bonds (walls included)")
      .def_property_readonly(
          "overlap", [](py::object self) { return view(self.cast<const PyChain&>().chain.overlap, self); },
          "static overlaps Delta_k = (F0/A_k)^(2/3) [m] of the N+1 bonds")
      .def_property_readonly(
          "F0", [](const PyChain& c) { return c.chain.precompression; }, "static precompression [N]")
      .def_property_readonly("types", &chain_types,
                             "bead types (1 or 2) as a uint8 array, or None for a chain built from radii")
      .def_property_readonly(
          "metadata", [](const PyChain& c) { return to_python(c.description); },
          "the chain as the tools describe it in their JSON ('chain' entry): F0_N, R1_m, xi, "
          "disorder, q, seed, realization, N, material, walls")
      .def(
          "linear_stiffness", [](const PyChain& c) { return to_numpy(linear_stiffness(c.chain)); },
          "B_k = (3/2) A_k^(2/3) F0^(1/3) [N/m] of the N+1 bonds: the linearized chain")
      .def("__repr__", [](const PyChain& c) {
        std::string what = c.description.contains("disorder") ? c.description["disorder"].get<std::string>()
                                                              : (c.types.empty() ? "radii" : "types");
        return "<granular.Chain " + what + ", N=" + std::to_string(c.chain.size()) +
               ", F0=" + format_number(c.chain.precompression) + " N>";
      });

  bind_random(m, "anderson", Disorder::anderson, "An Anderson-like chain: each bead type 1 with probability q.");
  bind_random(m, "rdm1", Disorder::rdm1,
              "A random-dimer chain RDM1: each dimer '1 1' with probability q, else '2 2' (odd N: the last bead "
              "of the last dimer is dropped).");
  bind_random(m, "rdm2", Disorder::rdm2, "A random-dimer chain RDM2: each dimer '1 2' with probability q, else '2 1'.");
  bind_random(m, "homogeneous", Disorder::homogeneous, "N type-1 beads (q, xi, seed and realization do not matter).");
  m.def(
      "random_chain",
      [](const std::string& disorder, long long N, double q, double xi, long long seed, long long realization,
         double F0, double R1, const Material& material) {
        return random_py_chain(disorder_of(disorder), chain_parameters(N, q, xi, seed, realization, F0, R1, material));
      },
      py::arg("disorder") = "A", py::arg("N") = 100, py::arg("q") = 0.5, py::arg("xi") = 0.5, py::arg("seed") = 1,
      py::arg("realization") = 0, py::arg("F0") = 10.0, py::arg("R1") = paper_r1, py::arg("material") = steel,
      (std::string("Realization `realization` of seed `seed` of a disorder kind: disorder = 'h' | 'A' | 'RDM1' | "
                   "'RDM2' (the tools' --disorder).") +
       chain_keywords_doc)
          .c_str());
  m.def(
      "diatomic",
      [](long long N, double xi, double F0, double R1, const Material& material) {
        ChainRecipe r = recipe_of(chain_parameters(N, 0.5, xi, 1, 0, F0, R1, material));
        r.given_types = Configuration(r.N);
        for (std::size_t i = 0; i < r.N; ++i) (*r.given_types)[i] = i % 2 == 0 ? 1 : 2;
        return py_chain(r, 0, "diatomic");
      },
      py::arg("N") = 100, py::arg("xi") = 0.5, py::arg("F0") = 10.0, py::arg("R1") = paper_r1,
      py::arg("material") = steel,
      "Alternating types 1, 2, 1, 2, ...: the ordered chain whose band edges fb1, fb2, fb3 granular.band_edges "
      "gives. N beads, xi = R2/R1 in (0, 1], F0 [N], R1 [m].");
  m.def(
      "from_types",
      [](const py::object& types, double xi, double F0, double R1, const Material& material) {
        Configuration t = types_vector(types, "types");
        const ChainParameters p = chain_parameters(static_cast<long long>(std::max<std::size_t>(t.size(), 2)), 0.5, xi,
                                                   1, 0, F0, R1, material);
        if (t.size() < 2) bad_value("types", ": " + std::to_string(t.size()) + " beads; a chain needs at least 2");
        ChainRecipe r = recipe_of(p);
        r.given_types = std::move(t);
        return py_chain(r, 0);
      },
      py::arg("types"), py::arg("xi") = 0.5, py::arg("F0") = 10.0, py::arg("R1") = paper_r1, py::arg("material") = steel,
      "A chain of given bead types: `types` is any array-like of 1 and 2 (type 1 has radius R1 [m], type 2 xi*R1), "
      "as a --config file holds them. F0 [N].");
  m.def(
      "from_radii",
      [](const py::object& radii, double F0, const Material& material) {
        std::vector<double> r = double_vector(radii, "radii");
        if (r.size() < 2) bad_value("radii", ": " + std::to_string(r.size()) + " beads; a chain needs at least 2");
        return py_chain({.given_radii = std::move(r), .F0 = F0, .material = material}, 0);
      },
      py::arg("radii"), py::arg("F0") = 10.0, py::arg("material") = steel,
      "A chain of beads of given radii [m] (any 1-D array-like, each finite and > 0) of one material, between flat "
      "walls of the same material, under precompression F0 [N].");
  m.def(
      "configuration",
      [](const std::string& disorder, double q, long long N, long long seed, long long realization) {
        validate_probability(q);
        auto t = realization_configuration(disorder_of(disorder), q, checked_size(N, "N", 2, 100000000),
                                           checked_size(seed, "seed"), checked_size(realization, "realization"));
        return to_numpy(std::vector<std::uint8_t>(t.begin(), t.end()));
      },
      py::arg("disorder") = "A", py::arg("q") = 0.5, py::arg("N") = 100, py::arg("seed") = 1, py::arg("realization") = 0,
      "The bead types (uint8 array of 1 and 2) of realization `realization` of seed `seed`: what random_chain builds "
      "its chain from. All xi of one (disorder, q, N, seed, realization) share it.");
  m.def(
      "read_types",
      [](const std::string& path) {
        check_readable(path);
        auto t = read_configuration_file(path);
        return to_numpy(std::vector<std::uint8_t>(t.begin(), t.end()));
      },
      py::arg("path"),
      "Bead types from a text file with one type (1 or 2) per line, '#' comments (the tools' --config). Raises OSError "
      "when it cannot be read, ValueError on a bad line.");
  m.def(
      "read_radii",
      [](const std::string& path) {
        check_readable(path);
        return to_numpy(read_radii_file(path));
      },
      py::arg("path"), "Radii [m] from a text file with one radius per line, '#' comments (the tools' --radii).");

  // --- the contact law -------------------------------------------------------------------------
  m.def(
      "hertz_coefficient",
      [](double radius_a, double radius_b, const Material& a, const Material& b) {
        if (!(radius_a > 0) || !(radius_b > 0))
          bad_value(radius_a > 0 ? "radius_b" : "radius_a", ": must be > 0 [m] (granular.flat_wall for a wall)");
        return hertz_coefficient(a, radius_a, b, radius_b);
      },
      py::arg("radius_a"), py::arg("radius_b") = flat_wall, py::arg("material_a") = steel, py::arg("material_b") = steel,
      "Hertz contact coefficient A [N/m^(3/2)] of two bodies of radii radius_a, radius_b [m] (force A delta^(3/2) at "
      "overlap delta); granular.flat_wall (infinity) for a flat wall.");
  m.def(
      "static_overlap",
      [](double contact, double F0) {
        finite(contact, "contact");
        finite(F0, "F0");
        return static_overlap(contact, F0);
      },
      py::arg("contact"), py::arg("F0"),
      "Static overlap Delta = (F0/A)^(2/3) [m] of a bond with coefficient A [N/m^(3/2)] "
      "under precompression F0 [N].");
  m.def(
      "linear_stiffness",
      [](double contact, double F0) {
        finite(contact, "contact");
        finite(F0, "F0");
        return linear_stiffness(contact, F0);
      },
      py::arg("contact"), py::arg("F0"),
      "Linear stiffness B = (3/2) A^(2/3) F0^(1/3) [N/m] of a bond with coefficient A [N/m^(3/2)] at F0 [N].");
  py::class_<FpuCoefficients>(m, "FpuCoefficients",
                              "Taylor coefficients of the Hertz force about the precompressed state: "
                              "F(x) ~ b1 x + b2 x^2 + b3 x^3 (the FPU chain).")
      .def_readonly("b1", &FpuCoefficients::b1, "(3/2) A^(2/3) F0^(1/3) [N/m]")
      .def_readonly("b2", &FpuCoefficients::b2, "(3/8) A^(4/3) F0^(-1/3) [N/m^2]")
      .def_readonly("b3", &FpuCoefficients::b3, "-(3/48) A^2 F0^(-1) [N/m^3]")
      .def_property_readonly("modulational_discriminant", &FpuCoefficients::modulational_discriminant,
                             "3 b1 b3 - 4 b2^2 [N^2/m^4]: band-edge waves are modulationally unstable only if > 0 "
                             "(always negative for Hertz)")
      .def("__repr__", [](const FpuCoefficients& f) {
        return "FpuCoefficients(b1=" + format_number(f.b1) + ", b2=" + format_number(f.b2) +
               ", b3=" + format_number(f.b3) + ")";
      });
  m.def(
      "fpu_coefficients", [](double contact, double F0) { return fpu_coefficients(contact, F0); }, py::arg("contact"),
      py::arg("F0"), "FPU coefficients b1, b2, b3 of a bond with coefficient A [N/m^(3/2)] at F0 [N] (both > 0).");
  m.def(
      "nonlinearity_ratio",
      [](double alpha, double contact, double F0) {
        finite(alpha, "alpha");
        finite(contact, "contact");
        finite(F0, "F0");
        return nonlinearity_ratio(alpha, contact, F0);
      },
      py::arg("alpha"), py::arg("contact"), py::arg("F0"),
      "epsilon = |alpha|/Delta: a displacement kick alpha [m] relative to the static overlap of a bond with "
      "coefficient A [N/m^(3/2)] at F0 [N]; infinite at F0 = 0 (no linear limit).");

  // --- correlations of one chain -----------------------------------------------------------------
  m.def(
      "cyclic_correlation",
      [](const py::object& types, long long max_distance) {
        Configuration t =
            py::isinstance<PyChain>(types) ? types.cast<const PyChain&>().types : types_vector(types, "types");
        if (t.empty()) bad_value("types", ": the chain was built from radii and has no bead types");
        const std::size_t d = checked_size(max_distance, "max_distance", 0, static_cast<long long>(t.size()) - 1);
        return to_numpy(cyclic_correlation(t, d));
      },
      py::arg("types"), py::arg("max_distance") = 10,
      "Pearson coefficient rho(d), d = 0..max_distance (< N), of the bead types (type 1 -> 0, type 2 -> 1) with their "
      "cyclic shift by d; `types` is a granular.Chain or an array of 1 and 2. NaN when the chain has one type only.");
  m.def(
      "correlation_theory",
      [](const std::string& disorder, double q, const py::object& distance) -> py::object {
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
      },
      py::arg("disorder"), py::arg("q"), py::arg("distance"),
      "Infinite-chain rho(d) of a disorder kind at probability q, for one distance or an array of distances [beads]; "
      "NaN where undefined (h; A at q in {0, 1}).");
}

}  // namespace granular::python
