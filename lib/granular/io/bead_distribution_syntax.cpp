#include "granular/io/bead_distribution_syntax.hpp"

#include <cmath>
#include <vector>

#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/model/material.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

/// validate(d), its message told as "<name> '<text>': <problem>".
BeadDistribution validated(BeadDistribution d, const std::string& name, const std::string& text) {
  try {
    validate(d);
  } catch (const InvalidInput& e) {
    throw InvalidInput(name, " '" + text + "': " + e.what());
  }
  if (d.kind != BeadDistribution::Kind::types) d.radii.clear();
  return d;
}

}  // namespace

BeadDistribution parse_bead_types(const std::string& text, bool by_mass, Disorder rule, const std::string& name) {
  BeadDistribution d;
  for (const std::string& item : parse_word_list(text, name)) {
    const auto colon = item.find(':');
    if (colon == std::string::npos)
      throw InvalidInput(name, " '" + item + "': expected " + (by_mass ? "MASS" : "RADIUS") + ":PROBABILITY");
    const double value = parse_number_list(item.substr(0, colon), name, 0, 1).at(0);
    if (!(value > 0) || !std::isfinite(value))
      throw InvalidInput(name, " '" + item + "': " + (by_mass ? "mass" : "radius") + " must be finite and > 0");
    d.radii.push_back(by_mass ? sphere_radius(steel, value) : value);
    d.probabilities.push_back(parse_number_list(item.substr(colon + 1), name, 0, 1).at(0));
  }
  d.rule = rule;
  return validated(d, name, text);
}

BeadDistribution parse_polydisperse(const std::string& text, const std::string& name) {
  std::vector<std::string> parts;
  for (std::size_t begin = 0;;) {
    const auto end = text.find(':', begin);
    parts.push_back(text.substr(begin, end - begin));
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  const auto number = [&](std::size_t i) { return parse_number_list(parts[i], name, 0, 1).at(0); };
  BeadDistribution d;
  if (parts[0] == "uniform" && parts.size() == 3) {
    d.kind = BeadDistribution::Kind::uniform;
    d.low = number(1), d.high = number(2);
    d.radii = {d.low, d.high};
  } else if (parts[0] == "normal" && parts.size() == 4) {
    d.kind = BeadDistribution::Kind::normal;
    d.mean = number(1), d.sd = number(2), d.minimum = number(3);
    d.radii = {d.mean, d.minimum};
  } else {
    throw InvalidInput(name, " '" + text + "': expected uniform:LO:HI or normal:MEAN:SD:MIN (metres)");
  }
  return validated(d, name, text);
}

std::string spell(const BeadDistribution& d) {
  const auto number = [](double x) { return format_number(x); };
  if (d.kind == BeadDistribution::Kind::uniform) return "uniform:" + number(d.low) + ":" + number(d.high);
  if (d.kind == BeadDistribution::Kind::normal)
    return "normal:" + number(d.mean) + ":" + number(d.sd) + ":" + number(d.minimum);
  std::string types;
  for (std::size_t t = 0; t < d.radii.size(); ++t) {
    if (t > 0) types += ',';
    types += number(d.radii[t]);
    types += ':';
    types += number(d.probabilities[t]);
  }
  return types;
}

}  // namespace granular
