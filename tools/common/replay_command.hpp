#pragma once
// The `spreading` command that computes one realization of a kicked-chain case alone, printed
// when a realization of an ensemble fails: every field of the case spelled as spreading's flags
// (the kick's and the run's from the rows that declare them: flag_table.hpp; numbers in shortest
// round-trip form), read back with spreading's own options (kicked_case.hpp)
// and checked by study/case_replay.hpp before it is printed.
#include <algorithm>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "granular/io/bead_distribution_syntax.hpp"
#include "granular/io/shell_quote.hpp"
#include "granular/number_format.hpp"
#include "granular/study/case_replay.hpp"
#include "kicked_case.hpp"

namespace granular::tool {

/// The flags of realization `r` of `c` as `spreading` reads them (no --output).
inline std::vector<std::string> replay_flags(const TransportCase& c, std::uint64_t r) {
  std::vector<std::string> a;
  const auto add = [&](const std::string& flag, const std::string& value) { a.insert(a.end(), {flag, value}); };
  const auto number = [](double x) { return format_number(x); };
  const ChainRecipe& chain = c.chain;
  if (const auto& b = chain.distribution) {
    const bool types = b->kind == BeadDistribution::Kind::types;
    add(types ? "--types" : "--polydisperse", spell(*b));
    if (types) add("--disorder", to_string(b->rule));
  } else if (chain.given_radii) {
    add("--radii", chain.source);
  } else if (const auto& q = chain.quasi) {
    spell_flags(quasi_flags(), options_of(*q), c, a);
    add("--R1", number(chain.R1));
  } else {
    if (chain.given_types) add("--config", chain.source);
    else add("--disorder", to_string(chain.disorder)), add("--q", number(chain.q));
    add("--xi", number(chain.xi));
    add("--R1", number(chain.R1));
  }
  if (chain.drawn()) {
    add("--N", chain.centred ? "auto" : std::to_string(chain.N));
    add("--seed", std::to_string(chain.seed));
    add("--realization", std::to_string(r));
  }
  add("--F0", number(chain.F0));
  if (chain.walls != WallShape::flat) add("--walls", "sphere");
  add("--ic", to_string(c.kick));
  const DynamicsOptions dynamics = options_of(c);
  spell_flags(kick_flags(), dynamics, c, a);
  spell_flags(mode_flags(), options_of(c.mode), c, a);
  spell_flags(run_flags(), dynamics, c, a);
  if (c.dynamics.integration.lyapunov.enabled) {
    a.emplace_back("--mle");
    add("--renormalize", std::to_string(dynamics.renormalize));
  }
  return a;
}

/// The case `spreading` reads from `arguments` (validated, its step settled as the tool does).
inline TransportCase read_kicked_case(const std::vector<std::string>& arguments) {
  CLI::App app;
  KickedCaseOptions o;
  add_kicked_case_options(app, o);
  std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11 reads them from the back
  app.parse(reversed);
  KickedCase k = kicked_case(o, false);
  validate_and_settle(k.c, o.dynamics, app.count("--dt") > 0);
  return k.c;
}

/// The `spreading` command that computes realization `r` of case `c` alone (study/case_replay.hpp),
/// so it meets exactly what the ensemble met; none when its flags cannot spell the case (`why`
/// says what differs). `argv0` (how this tool was called) says where `spreading` is.
inline std::optional<std::string> replay_command(const TransportCase& c, std::uint64_t r, const std::string& argv0,
                                                 std::string* why = nullptr) {
  const auto arguments = replay_arguments(c, r, {replay_flags, read_kicked_case}, why);
  if (!arguments) return std::nullopt;
  const auto slash = argv0.rfind('/');
  std::string command = shell_quote((slash == std::string::npos ? "" : argv0.substr(0, slash + 1)) + "spreading");
  for (const std::string& word : *arguments) command += " " + (word.starts_with("--") ? word : shell_quote(word));
  return command + " --output replay-" + std::to_string(r);
}

/// The replay command, or a sentence saying why there is none.
inline std::string replay_text(const TransportCase& c, std::uint64_t r, const std::string& argv0) {
  std::string why;
  const auto command = replay_command(c, r, argv0, &why);
  return command ? *command : "(no spreading command spells this case: it differs in " + why + ")";
}

}  // namespace granular::tool
