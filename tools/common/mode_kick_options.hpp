#pragma once
// The options of `--ic mode` (study/mode_kick.hpp): which linear mode of the chain starts the
// dynamics, by number or nearest a frequency, and its energy (without --energy, --alpha is the
// largest displacement of the mode shape).
#include <algorithm>
#include <vector>

#include <CLI/CLI.hpp>

#include "flag_table.hpp"
#include "granular/study/transport_study.hpp"

namespace granular::tool {

struct ModeKickOptions {
  long mode = 0;
  double mode_khz = -1, energy = 0;
};

/// The flags, each spelled by a replay only where a mode kick uses it.
inline const std::vector<Flag<ModeKickOptions>>& mode_flags() {
  using O = ModeKickOptions;
  static const std::vector<Flag<O>> flags{
      {"--mode", &O::mode, "--ic mode: the linear mode number K, 1..N by increasing frequency", false,
       [](const TransportCase& c) { return c.kick == Kick::mode && c.mode.mode != 0; }},
      {"--mode-khz", &O::mode_khz, "--ic mode: the linear mode nearest this frequency [kHz]", false,
       [](const TransportCase& c) { return c.kick == Kick::mode && c.mode.near_khz >= 0; }},
      {"--energy", &O::energy,
       "--ic mode: total energy of the initial state [J] (without it --alpha is the largest |u_n|)", false,
       [](const TransportCase& c) { return c.kick == Kick::mode && c.mode.energy != 0; }},
  };
  return flags;
}

inline void add_mode_kick_options(CLI::App& app, ModeKickOptions& o) { add_flags(app, o, mode_flags()); }

/// The options that give c's mode kick.
inline ModeKickOptions options_of(const ModeKick& m) {
  return {.mode = m.mode, .mode_khz = m.near_khz, .energy = m.energy};
}

/// Into `c`, whose mode kicks (if `kicks` holds one) use it: only a mode kick may use these options.
inline void apply(const ModeKickOptions& o, const std::vector<Kick>& kicks, TransportCase& c) {
  const bool given = o.mode != 0 || o.mode_khz >= 0 || o.energy != 0;
  if (given && std::find(kicks.begin(), kicks.end(), Kick::mode) == kicks.end())
    throw InvalidInput("--mode/--mode-khz/--energy: only with --ic mode");
  c.mode = {.mode = o.mode, .near_khz = o.mode_khz, .energy = o.energy, .amplitude = 0};
}

/// Into `c` (after the kick kind is set).
inline void apply(const ModeKickOptions& o, TransportCase& c) { apply(o, {c.kick}, c); }

}  // namespace granular::tool
