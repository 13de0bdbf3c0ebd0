#include "granular/model/material.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "granular/error.hpp"

namespace granular {

void validate(const Material& m, const char* what) {
  auto fail = [&](const char* field, double v, const char* rule) {
    throw InvalidInput(std::string(what) + ": " + field + " = " + std::to_string(v) + " (must be " + rule + ")");
  };
  if (!std::isfinite(m.young) || m.young <= 0) fail("Young modulus", m.young, "finite and > 0");
  if (!std::isfinite(m.poisson) || m.poisson <= -1 || m.poisson >= 0.5)
    fail("Poisson ratio", m.poisson, "in (-1, 0.5)");
  if (!std::isfinite(m.density) || m.density <= 0) fail("density", m.density, "finite and > 0");
}

double sphere_radius(const Material& material, double m) {
  return std::cbrt(m / (material.density * (4.0 / 3.0) * std::numbers::pi));
}

nlohmann::json describe(const Material& m) { return {{"E_Pa", m.young}, {"nu", m.poisson}, {"rho_kg_m3", m.density}}; }

}  // namespace granular
