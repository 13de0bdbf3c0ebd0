#include "granular/parameter_table.hpp"

#include <limits>

#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {

void detail::refuse_unmet(const std::string& name, const Needs& needs, const std::string& state) {
  std::string problem = ": takes effect only with `" + needs.choice + "`";
  if (!needs.values.empty()) problem += " " + needs.values.front();
  problem += state.empty()    ? ", which is not given"
             : state == "off" ? ", which is off"
                              : ", not `" + needs.choice + "` " + state;
  throw InvalidInput(name, problem);
}

void detail::refuse_out_of_range(const std::string& name, double value, const Range& range) {
  std::string bounds;
  if (range.low > -std::numeric_limits<double>::infinity())
    bounds += (range.low_open ? " and > " : " and >= ") + format_number(range.low);
  if (range.high < std::numeric_limits<double>::infinity())
    bounds += (range.high_open ? " and < " : " and <= ") + format_number(range.high);
  throw InvalidInput(name, " " + format_number(value) + ": must be finite" + bounds);
}

void detail::refuse_overridden(const std::string& name, const std::string& choice) {
  const std::size_t space = choice.find(' ');  // "disorder h": the choice, then its word
  const std::string told =
      space == std::string::npos ? "`" + choice + "`" : "`" + choice.substr(0, space) + "` " + choice.substr(space + 1);
  throw InvalidInput(name, ": takes no effect with " + told + "; leave one of them out");
}

std::string deprecation_note(const std::string& former, const std::string& now) {
  return former + " is deprecated: use " + now + " (the old spelling goes in the next minor version)";
}

std::string tell_parameters(const std::string& help, const std::function<std::string(const std::string&)>& told) {
  std::string out;
  std::size_t at = 0;
  for (std::size_t open; (open = help.find('`', at)) != std::string::npos;) {
    const std::size_t close = help.find('`', open + 1);
    if (close == std::string::npos) break;  // an unpaired backtick is text
    out += help.substr(at, open - at) + told(help.substr(open + 1, close - open - 1));
    at = close + 1;
  }
  return out + help.substr(at);
}

}  // namespace granular
