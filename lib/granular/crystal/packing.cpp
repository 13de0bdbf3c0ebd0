#include "granular/crystal/packing.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "granular/error.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/model/random_stream.hpp"
#include "granular/number_format.hpp"

namespace granular {

std::string_view to_string(Lattice lattice) { return lattice == Lattice::square ? "square" : "hexagonal"; }
std::string_view to_string(Boundary boundary) { return boundary == Boundary::walls ? "walls" : "periodic"; }

namespace {

void check_positive(const char* name, double value) {
  if (!(value > 0) || !std::isfinite(value))
    throw InvalidInput(name, " " + format_number(value) + ": must be finite and > 0");
}

void validate(const PackingSpec& spec) {
  const long least = spec.boundary == Boundary::periodic ? 3 : 2;
  // A periodic row of two would touch its neighbour twice, once through the torus.
  if (spec.Lx < least)
    throw InvalidInput("Lx", " " + std::to_string(spec.Lx) + ": must be >= " + std::to_string(least) + " with " +
                                 std::string(to_string(spec.boundary)));
  if (spec.Ly < least)
    throw InvalidInput("Ly", " " + std::to_string(spec.Ly) + ": must be >= " + std::to_string(least) + " with " +
                                 std::string(to_string(spec.boundary)));
  if (spec.lattice == Lattice::hexagonal && spec.Ly % 2 != 0)
    throw InvalidInput("Ly", " " + std::to_string(spec.Ly) + ": a hexagonal packing needs an even number of rows");
  check_positive("radius", spec.radius);
  validate(spec.material, "material");
  const auto beads = static_cast<std::size_t>(spec.Lx * spec.Ly);
  if (!spec.radii.empty()) {
    if (spec.radii.size() != beads)
      throw InvalidInput("radii",
                         ": " + std::to_string(spec.radii.size()) + " values for " + std::to_string(beads) + " beads");
    for (double r : spec.radii) check_positive("radii", r);
  }
  if (!spec.materials.empty()) {
    if (spec.materials.size() != beads)
      throw InvalidInput("materials", ": " + std::to_string(spec.materials.size()) + " values for " +
                                          std::to_string(beads) + " beads");
    for (const Material& m : spec.materials) validate(m, "materials");
  }
  if (spec.wall_material) validate(*spec.wall_material, "wall_material");
  if (spec.boundary == Boundary::walls) check_positive("precompression", spec.precompression);
  if (spec.boundary == Boundary::periodic && !(spec.strain > 0 && spec.strain < 0.1))
    throw InvalidInput("strain", " " + format_number(spec.strain) + ": must be in (0, 0.1) with periodic");
}

}  // namespace

PackingSpec disordered(PackingSpec spec, const PackingDisorder& disorder) {
  if (!(disorder.width >= 0 && disorder.width < 1))
    throw InvalidInput("width", " " + format_number(disorder.width) + ": must be in [0, 1)");
  validate(spec);
  const auto beads = static_cast<std::size_t>(spec.Lx * spec.Ly);
  RandomStream stream(disorder.seed, disorder.realization);
  auto draw = [&] { return 1 + disorder.width * (2 * stream.uniform() - 1); };
  if (disorder.kind == PackingDisorder::Kind::radius) {
    spec.radii.assign(beads, 0);
    for (double& r : spec.radii) r = spec.radius * draw();
    return spec;
  }
  if (spec.materials.empty()) spec.materials.assign(beads, spec.material);
  for (Material& m : spec.materials) {
    if (disorder.kind == PackingDisorder::Kind::mass) m.density *= draw();
    else m.young *= draw();
  }
  return spec;
}

Packing make_packing(const PackingSpec& spec) {
  validate(spec);
  Packing p;
  p.lattice = spec.lattice, p.boundary = spec.boundary, p.Lx = spec.Lx, p.Ly = spec.Ly;
  p.nominal_radius = spec.radius;
  const auto Lx = static_cast<std::size_t>(spec.Lx), Ly = static_cast<std::size_t>(spec.Ly);
  const std::size_t beads = Lx * Ly;
  p.radius = spec.radii.empty() ? std::vector<double>(beads, spec.radius) : spec.radii;
  p.material = spec.materials.empty() ? std::vector<Material>(beads, spec.material) : spec.materials;
  p.mass.resize(beads);
  for (std::size_t b = 0; b < beads; ++b) p.mass[b] = sphere_mass(p.material[b], p.radius[b]);

  // The reference lattice is uniformly compressed by the overlap two nominal beads have under F0
  // (walls) or by the imposed strain (periodic): for the perfect crystal it is the static state.
  const double R = spec.radius;
  if (spec.boundary == Boundary::walls) {
    p.precompression = spec.precompression;
    p.uniform_overlap = static_overlap(hertz_coefficient(spec.material, R, spec.material, R), spec.precompression);
  } else {
    p.uniform_overlap = 2 * R * spec.strain;
  }
  const double a = 2 * R - p.uniform_overlap;
  p.spacing = a;
  const bool hex = spec.lattice == Lattice::hexagonal;
  const double row_height = hex ? a * std::numbers::sqrt3 / 2 : a;
  p.x.resize(beads), p.y.resize(beads);
  for (std::size_t j = 0; j < Ly; ++j)
    for (std::size_t i = 0; i < Lx; ++i) {
      const double shift = hex && j % 2 == 1 ? 0.5 : 0.0;
      p.x[j * Lx + i] = a * (static_cast<double>(i) + shift);
      p.y[j * Lx + i] = row_height * static_cast<double>(j);
    }
  const bool periodic = spec.boundary == Boundary::periodic;
  if (periodic) p.box_x = a * static_cast<double>(Lx), p.box_y = row_height * static_cast<double>(Ly);

  // Neighbours as (column offset, row step, unit vector); a row step of 1 is the row above.
  auto connect = [&](std::size_t b, long di, long dj, double ex, double ey) {
    const long i = static_cast<long>(b % Lx) + di, j = static_cast<long>(b / Lx) + dj;
    if (!periodic && (i < 0 || i >= spec.Lx || j >= spec.Ly)) return;
    const auto wrap = [](long v, long n) { return static_cast<std::size_t>(((v % n) + n) % n); };
    const std::size_t c = wrap(j, spec.Ly) * Lx + wrap(i, spec.Lx);
    const double A = hertz_coefficient(p.material[b], p.radius[b], p.material[c], p.radius[c]);
    const int image_x = i < 0 ? -1 : i >= spec.Lx ? 1 : 0, image_y = j >= spec.Ly ? 1 : 0;
    p.contacts.push_back({b, c, ex, ey, A, (p.radius[b] - R) + (p.radius[c] - R) + p.uniform_overlap, image_x, image_y});
  };
  const double c60 = 0.5, s60 = std::numbers::sqrt3 / 2;
  for (std::size_t b = 0; b < beads; ++b) {
    connect(b, 1, 0, 1, 0);
    if (!hex) {
      connect(b, 0, 1, 0, 1);
    } else if ((b / Lx) % 2 == 0) {  // even row: the row above is shifted right by a/2
      connect(b, -1, 1, -c60, s60);
      connect(b, 0, 1, c60, s60);
    } else {
      connect(b, 0, 1, -c60, s60);
      connect(b, 1, 1, c60, s60);
    }
  }

  if (!periodic) {
    // A wall touches the beads nearest it: a whole column or row of the square packing; of the
    // hexagonal one the bottom and top rows, the even rows' first beads and the odd rows' last
    // (the other rows stand back by a/2). Its reference plane is R − Δ_wall from those centres.
    const Material* wall = spec.wall_material ? &*spec.wall_material : nullptr;
    const double wall_overlap =
        static_overlap(hertz_coefficient(spec.material, R, wall ? *wall : spec.material, flat_wall),
                       spec.precompression);
    auto touch = [&](std::size_t b, WallSide side) {
      const double A = hertz_coefficient(p.material[b], p.radius[b], wall ? *wall : p.material[b], flat_wall);
      p.wall_contacts.push_back({b, side, A, (p.radius[b] - R) + wall_overlap});
      p.wall_load[static_cast<std::size_t>(side)] += spec.precompression;
    };
    for (std::size_t j = 0; j < Ly; ++j) {
      if (!hex || j % 2 == 0) touch(j * Lx, WallSide::left);
      if (!hex || j % 2 == 1) touch(j * Lx + Lx - 1, WallSide::right);
    }
    for (std::size_t i = 0; i < Lx; ++i) {
      touch(i, WallSide::bottom);
      touch((Ly - 1) * Lx + i, WallSide::top);
    }
  }
  return p;
}

}  // namespace granular
