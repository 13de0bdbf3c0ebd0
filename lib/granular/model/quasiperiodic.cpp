#include "granular/model/quasiperiodic.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/model/contact_geometry.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/model/random_stream.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

constexpr double degree = std::numbers::pi / 180;

double cylinder_mass(const Material& m, double R) {
  return m.density * std::numbers::pi * R * R * cylinder_length_over_radius * R;
}

double cylinder_coefficient(const Material& m, double R, double angle_deg) {
  return hertz_coefficient(m, m, crossed_cylinders(R, angle_deg * degree));
}

/// The bond stiffness K of two spheres of radius R (S1's unit of k0).
double sphere_bond_stiffness(const Material& m, double R, double F0) {
  return linear_stiffness(hertz_coefficient(m, R, m, R), F0);
}

/// S1's mean on-site stiffness k0 [N/m]: the absolute one if given, else k0 × K.
double mean_onsite_stiffness(const Quasiperiodic& q, const Material& m, double R, double F0) {
  return q.k0_n_per_m > 0 ? q.k0_n_per_m : q.k0 * sphere_bond_stiffness(m, R, F0);
}

}  // namespace

std::string to_string(Quasiperiodic::Kind kind) {
  switch (kind) {
    case Quasiperiodic::Kind::s1: return "s1";
    case Quasiperiodic::Kind::s2: return "s2";
    case Quasiperiodic::Kind::cylinders: return "cylinders";
  }
  return "?";
}

Quasiperiodic::Kind parse_quasi_kind(const std::string& typed) {
  std::string word;  // kinds are names, whatever their case ("S1"), as disorders are
  for (const unsigned char c : typed) word += static_cast<char>(std::tolower(c));
  if (word == "s1") return Quasiperiodic::Kind::s1;
  if (word == "s2") return Quasiperiodic::Kind::s2;
  if (word == "cylinders" || word == "c") return Quasiperiodic::Kind::cylinders;
  throw InvalidInput("quasi", " '" + typed + "': expected s1 (on-site springs), s2 (masses) or cylinders (angles)");
}

double parse_ratio(const std::string& text) {
  if (text == "golden") return golden_mean;
  const auto number = [&](const std::string& s) {
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size())
      throw InvalidInput("ratio", " '" + text + "': expected golden, p/q or a number");
    return x;
  };
  const auto slash = text.find('/');
  const double beta =
      slash == std::string::npos ? number(text) : number(text.substr(0, slash)) / number(text.substr(slash + 1));
  if (!std::isfinite(beta) || !(beta > 0)) throw InvalidInput("ratio", " '" + text + "': must be finite and > 0");
  return beta;
}

double quasiperiodic_phase(const Quasiperiodic& q, std::uint64_t seed, std::uint64_t r) {
  if (q.phase) return *q.phase;
  return 2 * std::numbers::pi * RandomStream(seed, r).uniform();
}

void validate(const Quasiperiodic& q, double F0) {
  if (!std::isfinite(q.ratio) || !(q.ratio > 0))
    throw InvalidInput("ratio", " " + format_number(q.ratio) + ": the ratio beta must be finite and > 0");
  if (!std::isfinite(q.modulation))
    throw InvalidInput("modulation", " " + format_number(q.modulation) + ": must be finite");
  if (q.phase && !std::isfinite(*q.phase))
    throw InvalidInput("phase", " " + format_number(*q.phase) + ": must be finite");
  switch (q.kind) {
    case Quasiperiodic::Kind::s2:
      if (!(std::fabs(q.modulation) < 1))
        throw InvalidInput("modulation", " " + format_number(q.modulation) +
                                             ": masses m (1 + modulation cos) must stay > 0, so |modulation| < 1");
      break;
    case Quasiperiodic::Kind::s1:
      if (!std::isfinite(q.k0_n_per_m) || q.k0_n_per_m < 0)
        throw InvalidInput("k0_n_per_m", " " + format_number(q.k0_n_per_m) + ": must be finite and >= 0 [N/m]");
      if (!(F0 > 0) && q.k0_n_per_m == 0)
        throw InvalidInput("F0", " " + format_number(F0) +
                                     ": S1's k0 is in units of K, which needs F0 > 0 (or give k0 in N/m)");
      if (!std::isfinite(q.k0) || !(q.k0 > 0)) throw InvalidInput("k0", " " + format_number(q.k0) + ": must be > 0");
      if (!(std::fabs(q.modulation) < 1))
        throw InvalidInput("modulation", " " + format_number(q.modulation) +
                                             ": on-site stiffnesses k0 (1 + modulation cos) must stay > 0, so "
                                             "|modulation| < 1 (raise k0 for a larger amplitude)");
      break;
    case Quasiperiodic::Kind::cylinders:
      if (!(q.angle > 0 && q.angle < 180))
        throw InvalidInput("angle", " " + format_number(q.angle) + ": alpha0 must be in (0, 180) degrees");
      if (!(std::fabs(q.modulation) < 1) || !(q.angle * (1 + std::fabs(q.modulation)) < 180))
        throw InvalidInput("modulation", " " + format_number(q.modulation) +
                                             ": angles alpha0 (1 + modulation cos) must stay in (0, 180) degrees");
      break;
  }
}

CylinderContactExtent cylinder_contact_extent(const Quasiperiodic& q, double R, double F0, const Material& material) {
  CylinderContactExtent out;
  if (q.kind != Quasiperiodic::Kind::cylinders || !(F0 > 0)) return out;
  for (const double angle : {q.angle * (1 - std::fabs(q.modulation)), q.angle * (1 + std::fabs(q.modulation))}) {
    const ContactGeometry g = crossed_cylinders(R, angle * degree);
    const double a = contact_semi_major_axis(g, static_overlap(hertz_coefficient(material, material, g), F0)) / R;
    if (a > out.semi_axis_over_radius) out = {a, angle};
  }
  return out;
}

std::string check_cylinder_contacts(const Quasiperiodic& q, double R, double F0, const Material& material,
                                    const std::string& angle_name, const std::string& modulation_name) {
  const CylinderContactExtent extent = cylinder_contact_extent(q, R, F0, material);
  if (!(extent.semi_axis_over_radius > cylinder_ellipse_warning)) return "";
  // α0 is to blame when it alone goes that far, else the modulation.
  Quasiperiodic unmodulated = q;
  unmodulated.modulation = 0;
  const double alone = cylinder_contact_extent(unmodulated, R, F0, material).semi_axis_over_radius;
  const auto what = [&](bool angle) {
    return " " + format_number(angle ? q.angle : q.modulation) + ": at " +
           format_number(std::round(extent.angle_deg * 1000) / 1000) +
           " degrees the cylinders' contact ellipse (static, F0 = " + format_number(F0) + " N) has a semi-axis of " +
           format_number(std::round(extent.semi_axis_over_radius * 1000) / 1000) + " R";
  };
  if (extent.semi_axis_over_radius >= cylinder_ellipse_limit) {
    const bool angle = alone >= cylinder_ellipse_limit;
    throw InvalidInput(angle ? "angle" : "modulation",
                       what(angle) + ", at least " + format_number(cylinder_ellipse_limit) +
                           " R: a line contact, beyond the point-contact (Hertz) law; keep the angles farther from "
                           "parallel (docs/physics.md)");
  }
  const bool angle = alone > cylinder_ellipse_warning;
  return (angle ? angle_name : modulation_name) + what(angle) + ", above " + format_number(cylinder_ellipse_warning) +
         " R: the point-contact (Hertz) law assumes it much smaller than R";
}

Chain quasiperiodic_chain(const Quasiperiodic& q, std::size_t N, double R, double F0, const Material& material,
                          double phase) {
  validate(q, F0);
  check_cylinder_contacts(q, R, F0, material);
  if (q.kind != Quasiperiodic::Kind::cylinders) {
    Chain c = make_chain(std::vector<double>(N, R), F0, material);
    if (q.kind == Quasiperiodic::Kind::s2) {
      for (std::size_t i = 0; i < N; ++i) {
        c.mass[i] *= modulation_factor(q, phase, i + 1);
        c.inverse_mass[i] = 1 / c.mass[i];
      }
    } else {
      const double k0 = mean_onsite_stiffness(q, material, R, F0);
      c.onsite.resize(N);
      for (std::size_t i = 0; i < N; ++i) c.onsite[i] = k0 * modulation_factor(q, phase, i + 1);
    }
    return c;
  }
  if (N < 2) throw InvalidInput("N", " " + std::to_string(N) + ": a chain needs at least 2 beads");
  validate(material, "material");
  if (!std::isfinite(F0) || F0 < 0) throw InvalidInput("F0", " " + format_number(F0) + ": must be finite and >= 0");
  Chain c;
  c.precompression = F0;
  c.radius.assign(N, R);
  c.mass.assign(N, cylinder_mass(material, R));
  c.inverse_mass.assign(N, 1 / c.mass[0]);
  c.contact.resize(N + 1);
  c.overlap.resize(N + 1);
  for (std::size_t k = 0; k <= N; ++k) {
    c.contact[k] = cylinder_coefficient(material, R, q.angle * modulation_factor(q, phase, k));
    c.overlap[k] = static_overlap(c.contact[k], F0);
  }
  return c;
}

std::vector<Chain> quasiperiodic_local_chains(const Quasiperiodic& q, double R, double F0, const Material& material) {
  validate(q, F0);
  // Factors 1 + λ cos at the modulation's ends (and, for angles, 90° where the contact is stiffest).
  std::vector<double> factors{1 - std::fabs(q.modulation), 1 + std::fabs(q.modulation)};
  if (q.kind == Quasiperiodic::Kind::cylinders && 90 / q.angle > factors[0] && 90 / q.angle < factors[1])
    factors.push_back(90 / q.angle);
  const Chain base = quasiperiodic_chain(q, 3, R, F0, material, 0);
  std::vector<Chain> out;
  const std::size_t sites = q.kind == Quasiperiodic::Kind::cylinders ? 4 : 3, m = factors.size();
  std::size_t combinations = 1;
  for (std::size_t i = 0; i < sites; ++i) combinations *= m;
  for (std::size_t code = 0; code < combinations; ++code) {
    Chain c = base;
    std::size_t rest = code;
    for (std::size_t i = 0; i < sites; ++i, rest /= m) {
      const double f = factors[rest % m];
      if (q.kind == Quasiperiodic::Kind::s2) {
        c.mass[i] = sphere_mass(material, R) * f;
        c.inverse_mass[i] = 1 / c.mass[i];
      } else if (q.kind == Quasiperiodic::Kind::s1) {
        c.onsite[i] = base.onsite[i] / modulation_factor(q, 0, i + 1) * f;
      } else {
        c.contact[i] = cylinder_coefficient(material, R, q.angle * f);
        c.overlap[i] = static_overlap(c.contact[i], F0);
      }
    }
    out.push_back(std::move(c));
  }
  return out;
}

double quasiperiodic_omega_bound(const Quasiperiodic& q, double R, double F0, const Material& material) {
  const double lightest = 1 - std::fabs(q.modulation), heaviest = 1 + std::fabs(q.modulation);
  if (q.kind == Quasiperiodic::Kind::cylinders) {
    // The coefficient is least at 90° and grows as the axes turn parallel: its largest value is at
    // an end of the range of angles (90° is tried too, harmlessly).
    double stiffest = 0;
    for (double a : {q.angle * lightest, q.angle * heaviest, 90.0})
      if (a >= q.angle * lightest && a <= q.angle * heaviest)
        stiffest = std::fmax(stiffest, linear_stiffness(cylinder_coefficient(material, R, a), F0));
    return std::sqrt(4 * stiffest / cylinder_mass(material, R));
  }
  const double wall = linear_stiffness(hertz_coefficient(material, R, material, flat_wall), F0);
  const double m = sphere_mass(material, R);
  if (q.kind == Quasiperiodic::Kind::s2) return std::sqrt(4 * wall / (m * lightest));
  return std::sqrt((4 * wall + mean_onsite_stiffness(q, material, R, F0) * heaviest) / m);
}

nlohmann::json describe(const Quasiperiodic& q) {
  nlohmann::json j;
  j["kind"] = to_string(q.kind);
  j["modulation"] = q.modulation;
  j["ratio"] = q.ratio;
  if (q.phase) j["phase_rad"] = *q.phase;
  else j["phase_rule"] = "uniform in [0, 2pi) per realization (seed, realization)";
  if (q.kind == Quasiperiodic::Kind::cylinders) {
    j["angle_deg"] = q.angle;
    j["cylinder_length_over_radius"] = cylinder_length_over_radius;
  }
  if (q.kind == Quasiperiodic::Kind::s1) {
    if (q.k0_n_per_m > 0) j["k0_N_per_m"] = q.k0_n_per_m;
    else j["k0_over_K"] = q.k0;
  }
  return j;
}

Quasiperiodic parse_quasiperiodic(const nlohmann::json& j) {
  Quasiperiodic q;
  try {
    q.kind = parse_quasi_kind(j.at("kind").get<std::string>());
    q.modulation = j.at("modulation").get<double>();
    q.ratio = j.at("ratio").get<double>();
    if (j.contains("phase_rad")) q.phase = j.at("phase_rad").get<double>();
    if (j.contains("angle_deg")) q.angle = j.at("angle_deg").get<double>();
    if (j.contains("k0_over_K")) q.k0 = j.at("k0_over_K").get<double>();
    if (j.contains("k0_N_per_m")) q.k0_n_per_m = j.at("k0_N_per_m").get<double>();
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInput("quasiperiodic", std::string(": ") + e.what());
  }
  return q;
}

}  // namespace granular
