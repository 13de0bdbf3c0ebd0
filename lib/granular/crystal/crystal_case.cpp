#include "granular/crystal/crystal_case.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "granular/detail/enum_names.hpp"
#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

using Crystal = CrystalCase;
using P = Parameter<Crystal>;

constexpr auto lattice_names =
    detail::enum_names<Lattice>("lattice", {{Lattice::square, "square"}, {Lattice::hexagonal, "hexagonal"}});
constexpr auto boundary_names =
    detail::enum_names<Boundary>("boundary", {{Boundary::walls, "walls"}, {Boundary::periodic, "periodic"}});
constexpr auto disorder_names =
    detail::enum_names<PackingDisorder::Kind>("disorder", {{PackingDisorder::Kind::mass, "mass"},
                                                           {PackingDisorder::Kind::material, "material"},
                                                           {PackingDisorder::Kind::radius, "radius"}});

constexpr auto method_names = detail::enum_names<NearestMethod>("method", {{NearestMethod::automatic, "auto"},
                                                                           {NearestMethod::arpack, "arpack"},
                                                                           {NearestMethod::slepc, "slepc"}});

// The window's text form, lo:hi [kHz] (parse_interval: finite, lo < hi); empty: none.
void read_window(Crystal& c, const std::string& text) {
  if (text.empty()) return c.window.reset();
  const Interval i = parse_interval(text, "window");
  c.window = {i.start, i.stop};
}
std::string write_window(const Crystal& c) {
  return c.window ? format_number(c.window->first) + ":" + format_number(c.window->second) : "";
}

void read_lattice(Crystal& c, const std::string& word) { c.packing.lattice = lattice_names.parse(word); }
std::string write_lattice(const Crystal& c) { return std::string(lattice_names.name_of(c.packing.lattice)); }
void read_boundary(Crystal& c, const std::string& word) { c.packing.boundary = boundary_names.parse(word); }
std::string write_boundary(const Crystal& c) { return std::string(boundary_names.name_of(c.packing.boundary)); }
void read_disorder(Crystal& c, const std::string& word) { c.disorder.kind = disorder_names.parse(word); }
std::string write_disorder(const Crystal& c) { return std::string(disorder_names.name_of(c.disorder.kind)); }
void read_method(Crystal& c, const std::string& word) { c.method = method_names.parse(word); }
std::string write_method(const Crystal& c) { return std::string(method_names.name_of(c.method)); }

}  // namespace

const ParameterTable<CrystalCase>& crystal_parameters() {
  using S = PackingSpec;
  using D = PackingDisorder;
  static const ParameterTable<Crystal> table{
      P{"lattice",
        {},
        {read_lattice, write_lattice},
        "square | hexagonal (triangular lattice, horizontal rows, odd rows shifted by one radius)"}
          .as_word(),
      P{"boundary",
        {},
        {read_boundary, write_boundary},
        "walls (four flat walls pushing with `precompression` per bead they touch) | periodic (a torus under "
        "`strain`)"}
          .as_word(),
      {"Lx", path<Crystal>(&Crystal::packing, &S::Lx), "beads per row (>= 2; periodic >= 3)"},
      {"Ly", path<Crystal>(&Crystal::packing, &S::Ly), "rows (>= 2; periodic >= 3; hexagonal: even)"},
      {"radius", path<Crystal>(&Crystal::packing, &S::radius), "nominal bead radius R [m] (steel beads, steel walls)"},
      P{"precompression", path<Crystal>(&Crystal::packing, &S::precompression),
        "walls: static force F0 [N] each wall applies per bead it touches"}
          .needing("boundary", {"walls"}),
      P{"strain", path<Crystal>(&Crystal::packing, &S::strain),
        "periodic: uniform compressive strain, neighbours 2R(1 - strain) apart, in (0, 0.1)"}
          .needing("boundary", {"periodic"}),
      P{"disorder",
        {},
        {read_disorder, write_disorder},
        "what `width` draws per bead: mass (density, same size and stiffness) | material (Young modulus) | radius "
        "(polydisperse: the static state is solved)"}
          .as_word()
          .needing("width"),
      {"width", path<Crystal>(&Crystal::disorder, &D::width),
       "relative disorder w in [0, 1): each bead's value is nominal x (1 + w u), u uniform on [-1, 1]; 0: a "
       "perfect crystal"},
      P{"seed", path<Crystal>(&Crystal::disorder, &D::seed), "random seed of the disorder (bead b takes the b-th draw)"}
          .needing("width"),
      {"near", &Crystal::near,
       "the `count` modes nearest this frequency [kHz] by sparse shift-invert (default: every mode, dense LAPACK)",
       false},
      P{"count", &Crystal::count, "with `near`: how many modes (1 <= count < 2 Lx Ly)"}.needing("near"),
      P{"method",
        {},
        {read_method, write_method},
        "with `near`: auto (slepc from 1e5 beads, where it is the faster, in a build with SLEPc; else arpack) | "
        "arpack (one process, sparse LDL^T) | slepc (Krylov-Schur with MUMPS over the MPI ranks of mpirun)"}
          .as_word()
          .needing("near"),
      P{"window",
        {},
        {read_window, write_window},
        "every mode in lo:hi [kHz] by SLEPc's spectrum slicing (the count from the factorization's inertia, "
        "so none is missed; over the MPI ranks of mpirun), instead of `near`",
        false}
          .as_word(),
      {"ratio_lo", &Crystal::ratio_lo,
       "lower end [kHz] of the window of the level-spacing ratio <r> (default: no limit)", false},
      {"ratio_hi", &Crystal::ratio_hi, "upper end [kHz] of that window (default: no limit)", false},
      {"vectors", &Crystal::vectors, "also write every computed mode's bead displacements (PREFIX-modes.csv)"}};
  return table;
}

void validate(const CrystalCase& c) {
  refuse_unmet_needs(c, crystal_parameters());
  // Here, not only in disordered(): a width that is not > 0 (NaN, −inf) would otherwise pass as
  // "no disorder" and run the perfect crystal.
  if (!(c.disorder.width >= 0 && c.disorder.width < 1))
    throw InvalidInput("width", " " + format_number(c.disorder.width) + ": must be in [0, 1)");
  if (c.near && c.window) throw InvalidInput("window", ": not with `near` (one choice of modes)");
  if (c.window && c.window->first < 0)
    throw InvalidInput("window", " " + write_window(c) + ": frequencies are >= 0 [kHz]");
  if (c.near && (!std::isfinite(*c.near) || *c.near < 0))
    throw InvalidInput("near", " " + format_number(*c.near) + ": must be a finite frequency >= 0 [kHz]");
  const long dof = 2 * c.packing.Lx * c.packing.Ly;
  if (c.near && (c.count < 1 || c.count >= dof))
    throw InvalidInput("count", " " + std::to_string(c.count) + ": must be in [1, " + std::to_string(dof - 1) +
                                    "] for " + std::to_string(dof) + " degrees of freedom");
  for (const auto& [name, end] : {std::pair{"ratio_lo", c.ratio_lo}, std::pair{"ratio_hi", c.ratio_hi}})
    if (end && !std::isfinite(*end)) throw InvalidInput(name, ": must be finite [kHz]");
  if (c.ratio_lo && c.ratio_hi && !(*c.ratio_lo < *c.ratio_hi))
    throw InvalidInput("ratio_hi",
                       " " + format_number(*c.ratio_hi) + ": must be above `ratio_lo` " + format_number(*c.ratio_lo));
}

}  // namespace granular
