#include "granular/model/bead_distribution.hpp"

#include <cmath>
#include <numeric>
#include <sstream>

#include "granular/error.hpp"
#include "granular/model/random_stream.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

void check_radius(double r, const char* field) {
  if (!std::isfinite(r) || !(r > 0)) throw InvalidInput(field, " " + format_number(r) + ": must be finite and > 0 [m]");
}

/// Upper tail of the standard normal, Q(x) = P(X > x).
double upper_tail(double x) { return 0.5 * std::erfc(x / std::sqrt(2.0)); }

}  // namespace

void validate(const BeadDistribution& d) {
  switch (d.kind) {
    case BeadDistribution::Kind::types: {
      if (d.radii.empty()) throw InvalidInput("radii", ": at least one bead type");
      if (d.probabilities.size() != d.radii.size())
        throw InvalidInput("probabilities", ": " + std::to_string(d.probabilities.size()) + " for " +
                                                std::to_string(d.radii.size()) + " types");
      for (double r : d.radii) check_radius(r, "radii");
      for (double p : d.probabilities)
        if (!(p >= 0 && p <= 1)) throw InvalidInput("probabilities", " " + format_number(p) + ": must be in [0, 1]");
      const double sum = std::accumulate(d.probabilities.begin(), d.probabilities.end(), 0.0);
      if (std::fabs(sum - 1) > 1e-9) throw InvalidInput("probabilities", ": sum to " + format_number(sum) + ", not 1");
      if (d.rule == Disorder::homogeneous) throw InvalidInput("rule", ": h draws nothing; use A, RDM1 or RDM2");
      if (d.rule == Disorder::rdm2 && d.radii.size() != 2)
        throw InvalidInput("rule",
                           ": RDM2 (dimers 12 / 21) needs exactly two types, not " + std::to_string(d.radii.size()));
      return;
    }
    case BeadDistribution::Kind::uniform:
      check_radius(d.low, "low");
      check_radius(d.high, "high");
      if (d.high < d.low)
        throw InvalidInput("high", " " + format_number(d.high) + ": below low " + format_number(d.low));
      return;
    case BeadDistribution::Kind::normal:
      check_radius(d.mean, "mean");
      check_radius(d.sd, "sd");
      check_radius(d.minimum, "minimum");
      if (d.minimum >= d.mean + 8 * d.sd)
        throw InvalidInput("minimum",
                           " " + format_number(d.minimum) + ": more than 8 sd above the mean (no radii left)");
      return;
  }
}

double radius_from_uniform(const BeadDistribution& d, double u) {
  if (d.kind == BeadDistribution::Kind::uniform) return d.low + (d.high - d.low) * u;
  // Truncated normal by its inverse CDF on the upper tail (accurate where the tail is thin):
  // find z ≥ a with Q(z) = (1 − u) Q(a), a = (minimum − mean)/sd, by bisection (Q decreases).
  const double a = (d.minimum - d.mean) / d.sd, target = (1 - u) * upper_tail(a);
  double lo = a, hi = std::max(a, 0.0) + 40;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::fabs(hi)); ++it) {
    const double mid = (lo + hi) / 2;
    (upper_tail(mid) > target ? lo : hi) = mid;
  }
  return std::max(d.minimum, d.mean + d.sd * (lo + hi) / 2);
}

std::vector<double> realization_radii(const BeadDistribution& d, std::size_t n, std::uint64_t seed,
                                      std::uint64_t realization) {
  validate(d);
  RandomStream stream(seed, realization);
  std::vector<double> radii(n);
  if (d.kind != BeadDistribution::Kind::types) {
    for (double& r : radii) r = radius_from_uniform(d, stream.uniform());
    return radii;
  }
  // The first type t whose cumulative probability exceeds u; the last type takes the rest, so
  // rounding in the sum never leaves a bead without a type. For two types: u < p1 → type 1, the
  // comparison of sample_configuration.
  const auto type_of = [&](double u) {
    double cumulative = 0;
    for (std::size_t t = 0; t + 1 < d.probabilities.size(); ++t) {
      cumulative += d.probabilities[t];
      if (u < cumulative) return t;
    }
    return d.probabilities.size() - 1;
  };
  if (d.rule == Disorder::anderson) {
    for (double& r : radii) r = d.radii[type_of(stream.uniform())];
    return radii;
  }
  for (std::size_t i = 0; i < n; i += 2) {  // odd N: the last dimer loses its second bead
    const double u = stream.uniform();
    std::size_t a = type_of(u), b = a;
    if (d.rule == Disorder::rdm2) {
      a = u < d.probabilities[0] ? 0 : 1;
      b = 1 - a;
    }
    radii[i] = d.radii[a];
    if (i + 1 < n) radii[i + 1] = d.radii[b];
  }
  return radii;
}

std::string describe(const BeadDistribution& d) {
  std::ostringstream out;
  switch (d.kind) {
    case BeadDistribution::Kind::types:
      out << "types(" << to_string(d.rule) << ";";
      for (std::size_t t = 0; t < d.radii.size(); ++t)
        out << (t ? "," : "") << format_number(d.radii[t]) << ":" << format_number(d.probabilities[t]);
      out << ")";
      break;
    case BeadDistribution::Kind::uniform:
      out << "uniform(" << format_number(d.low) << "," << format_number(d.high) << ")";
      break;
    case BeadDistribution::Kind::normal:
      out << "normal(" << format_number(d.mean) << "," << format_number(d.sd) << ",min " << format_number(d.minimum)
          << ")";
      break;
  }
  return out.str();
}

BeadDistribution parse_bead_distribution(const std::string& text) {
  const auto bad = [&] {
    return InvalidInput("beads", " '" + text + "': not a bead distribution as describe() writes it");
  };
  const auto open = text.find('('), close = text.rfind(')');
  if (open == std::string::npos || close != text.size() - 1) throw bad();
  const std::string kind = text.substr(0, open), body = text.substr(open + 1, close - open - 1);
  const auto number = [&](const std::string& s) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(s, &used);
    } catch (const std::exception&) {
      throw bad();
    }
    if (used != s.size()) throw bad();
    return x;
  };
  const auto split = [](const std::string& s, char by) {
    std::vector<std::string> parts;
    for (std::size_t begin = 0;;) {
      const auto end = s.find(by, begin);
      parts.push_back(s.substr(begin, end - begin));
      if (end == std::string::npos) return parts;
      begin = end + 1;
    }
  };
  BeadDistribution d;
  if (kind == "types") {
    const auto semicolon = body.find(';');
    if (semicolon == std::string::npos) throw bad();
    d.rule = parse_disorder(body.substr(0, semicolon));
    for (const std::string& item : split(body.substr(semicolon + 1), ',')) {
      const auto pair = split(item, ':');
      if (pair.size() != 2) throw bad();
      d.radii.push_back(number(pair[0]));
      d.probabilities.push_back(number(pair[1]));
    }
  } else if (kind == "uniform") {
    const auto parts = split(body, ',');
    if (parts.size() != 2) throw bad();
    d.kind = BeadDistribution::Kind::uniform;
    d.low = number(parts[0]), d.high = number(parts[1]);
  } else if (kind == "normal") {
    const auto parts = split(body, ',');
    if (parts.size() != 3 || parts[2].rfind("min ", 0) != 0) throw bad();
    d.kind = BeadDistribution::Kind::normal;
    d.mean = number(parts[0]), d.sd = number(parts[1]), d.minimum = number(parts[2].substr(4));
  } else {
    throw bad();
  }
  return d;
}

}  // namespace granular
