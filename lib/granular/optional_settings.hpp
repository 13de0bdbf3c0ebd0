#pragma once
// The settings of something a run may do (an observer: the energy map, g(ν)) together with whether
// it does it. Unlike std::optional the settings are kept while it is off, so that a parameter table
// (parameter_table.hpp) can reach them as fields of the case, with the struct's own defaults, and
// check them whether or not the output is asked. Reads as an optional:
//
//   run.energy_map = EnergyMapObserver::Settings{.samples = 200};  // on, with these settings
//   if (run.energy_map) use(run.energy_map->samples);
//   run.energy_map.reset();                                        // off; the settings stay
#include <utility>

namespace granular {

template <class Settings>
struct OptionalSettings {
  bool on = false;
  Settings settings{};

  OptionalSettings() = default;
  OptionalSettings(Settings s) : on(true), settings(std::move(s)) {}  // NOLINT: reads as an optional's assignment

  explicit operator bool() const { return on; }
  bool has_value() const { return on; }
  void reset() { on = false; }
  const Settings& operator*() const { return settings; }
  Settings& operator*() { return settings; }
  const Settings* operator->() const { return &settings; }
  Settings* operator->() { return &settings; }
};

}  // namespace granular
