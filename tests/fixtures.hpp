#pragma once
// Canonical chains and the SPEC reference table, shared by the test suites.
#include <cmath>
#include <cstddef>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"

namespace granular::fixtures {

/// The number of steps τ that make up `duration` [s] (both given as round decimals).
inline std::size_t steps_for(double duration, double tau) {
  return static_cast<std::size_t>(std::llround(duration / tau));
}

inline constexpr double r1 = 4.76e-3;  ///< the paper's type-1 radius [m]

struct Reference {
  double value, tolerance;
};

/// data/reference_values.csv as quantity → (value, tolerance).
inline const std::map<std::string, Reference>& reference_values() {
  static const std::map<std::string, Reference> table = [] {
    std::map<std::string, Reference> t;
    std::ifstream in(std::string(GRANULAR_DATA_DIR) + "/reference_values.csv");
    if (!in) throw std::runtime_error("cannot open data/reference_values.csv");
    std::string line;
    bool header = true;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      if (header) {
        header = false;
        continue;
      }
      std::stringstream row(line);
      std::string name, value, tolerance;
      std::getline(row, name, ',');
      std::getline(row, value, ',');
      std::getline(row, tolerance, ',');
      t[name] = {std::stod(value), std::stod(tolerance)};
    }
    return t;
  }();
  return table;
}

inline Reference reference(const std::string& name) {
  auto it = reference_values().find(name);
  if (it == reference_values().end()) throw std::runtime_error("no reference value " + name);
  return it->second;
}

/// N type-1 beads between flat walls.
inline Chain homogeneous(std::size_t n, double f0 = 10, double radius = r1) {
  return make_chain(std::vector<double>(n, radius), f0);
}

/// N type-1 beads whose end bonds equal the bulk bond: the walls are fixed beads of radius R1.
inline Chain homogeneous_bulk_walls(std::size_t n, double f0 = 10) {
  ChainSpec spec;
  spec.radii.assign(n, r1);
  spec.materials = {steel};
  spec.left_wall.radius = spec.right_wall.radius = r1;
  spec.precompression = f0;
  return make_chain(spec);
}

/// Ordered 1,2,1,2,… chain.
inline Chain diatomic(std::size_t n, double xi, double f0 = 10) {
  Configuration types(n);
  for (std::size_t i = 0; i < n; ++i) types[i] = i % 2 == 0 ? 1 : 2;
  return make_chain(radii_of(types, r1, xi), f0);
}

/// Realization r of seed 7 of a disorder kind.
inline Chain random_chain(Disorder kind, std::size_t n, double xi, double q, std::uint64_t r, double f0 = 10) {
  return make_chain(radii_of(realization_configuration(kind, q, n, 7, r), r1, xi), f0);
}

}  // namespace granular::fixtures
