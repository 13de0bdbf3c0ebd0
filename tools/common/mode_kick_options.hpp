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

/// The flags of a mode kick.
inline const std::vector<Flag<ModeKickOptions>>& mode_flags() {
  using O = ModeKickOptions;
  static const std::vector<Flag<O>> flags{
      {"--mode", &O::mode, "--ic mode: the linear mode number K, 1..N by increasing frequency", false},
      {"--mode-khz", &O::mode_khz, "--ic mode: the linear mode nearest this frequency [kHz]", false},
      {"--energy", &O::energy,
       "--ic mode: total energy of the initial state [J] (without it --alpha is the largest |u_n|)", false},
  };
  return flags;
}

inline void add_mode_kick_options(CLI::App& app, ModeKickOptions& o) { add_flags(app, o, mode_flags()); }

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
