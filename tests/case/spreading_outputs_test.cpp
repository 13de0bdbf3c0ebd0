// The outputs of a spreading run, rows over the case for the tool and Python: beads counted from 1
// inside the chain, every sampling count at least 2 (the stride at least 1), displacement or
// velocity spectra; each refusal names the parameter, and the rows set the case's observers.
#include "granular/case/spreading_outputs.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "granular/error.hpp"

namespace granular {
namespace {

TransportCase outputs_case() {
  TransportCase c;
  c.chain.N = 101;
  return c;
}

/// The rows' text form of `name` read from `text` into `c`.
void read_output(TransportCase& c, const std::string& name, const std::string& text) {
  parameter(spreading_output_parameters(), name).text->read(c, text);
}

/// The parameter the case `set` makes is refused for, or "" when it is taken.
std::string outputs_refused(const std::function<void(TransportCase&)>& set) {
  TransportCase c = outputs_case();
  try {
    set(c);
    validate_outputs(c);
  } catch (const InvalidInput& e) {
    return e.parameter();
  }
  return "";
}

TEST(SpreadingOutputs, TheRowsSetTheObservers) {
  TransportCase c = outputs_case();
  validate_outputs(c);  // the defaults ask for nothing
  EXPECT_TRUE(c.dynamics.forces.sites.empty());
  EXPECT_FALSE(c.dynamics.energy_map);
  EXPECT_FALSE(c.dynamics.spectrum);

  read_output(c, "forces_at", "1,51,101");
  read_output(c, "spectrum_of", "velocity");
  const auto& table = spreading_output_parameters();
  const auto set = [&](const std::string& name, auto value) {
    using T = decltype(value);
    std::get<Ref<TransportCase, T>>(parameter(table, name).field)(c) = value;
  };
  set("force_samples", 20ul);
  set("energy_map", true);
  set("map_samples", 10ul);
  set("map_stride", 3ul);
  set("spectral_density", true);
  set("spectrum_samples", 64ul);
  validate_outputs(c);
  EXPECT_EQ(c.dynamics.forces.sites, (std::vector<std::size_t>{0, 50, 100}));  // 0-based
  EXPECT_EQ(c.dynamics.forces.samples, 20u);
  ASSERT_TRUE(c.dynamics.energy_map);
  EXPECT_EQ(c.dynamics.energy_map->samples, 10u);
  EXPECT_EQ(c.dynamics.energy_map->stride, 3u);
  ASSERT_TRUE(c.dynamics.spectrum);
  EXPECT_EQ(c.dynamics.spectrum->samples, 64u);
  EXPECT_EQ(c.dynamics.spectrum->source, SpectrumSource::velocity);

  read_output(c, "forces_at", "7");  // read again: replaced, not added to
  EXPECT_EQ(c.dynamics.forces.sites, (std::vector<std::size_t>{6}));
  c.dynamics.energy_map.reset();
  EXPECT_FALSE(c.dynamics.energy_map);
  EXPECT_EQ(c.dynamics.energy_map->samples, 10u) << "off, its settings kept";
}

TEST(SpreadingOutputs, ABadChoiceIsRefusedByName) {
  using C = TransportCase&;
  EXPECT_EQ(outputs_refused([](C c) { read_output(c, "forces_at", "0"); }), "forces_at");
  EXPECT_EQ(outputs_refused([](C c) { read_output(c, "forces_at", "50,102"); }), "forces_at");
  EXPECT_EQ(outputs_refused([](C c) { read_output(c, "forces_at", "101"); }), "");
  EXPECT_EQ(outputs_refused([](C c) { read_output(c, "forces_at", "101"), c.dynamics.forces.samples = 1; }),
            "force_samples");
  EXPECT_EQ(outputs_refused([](C c) { c.dynamics.forces.samples = 1; }), "force_samples");  // and without beads
  EXPECT_EQ(outputs_refused([](C c) { c.dynamics.energy_map = EnergyMapObserver::Settings{.samples = 1}; }),
            "map_samples");
  EXPECT_EQ(outputs_refused([](C c) { c.dynamics.energy_map = EnergyMapObserver::Settings{.samples = 2}; }), "");
  // takes effect only with a map: not ignored
  EXPECT_EQ(outputs_refused([](C c) { c.dynamics.energy_map->samples = 2; }), "map_samples");
  EXPECT_EQ(outputs_refused([](C c) { c.dynamics.energy_map = EnergyMapObserver::Settings{.samples = 100000001}; }),
            "map_samples");
  EXPECT_EQ(outputs_refused([](C c) { c.dynamics.energy_map = EnergyMapObserver::Settings{.stride = 0}; }),
            "map_stride");
  EXPECT_EQ(outputs_refused([](C c) { c.dynamics.spectrum = SpectralDensityObserver::Settings{.samples = 1}; }),
            "spectrum_samples");
  EXPECT_EQ(outputs_refused([](C c) { read_output(c, "spectrum_of", "force"); }), "spectrum_of");
}

TEST(SpreadingOutputs, TheMessageSaysWhereTheChainIs) {
  TransportCase c = outputs_case();
  read_output(c, "forces_at", "3,102");
  try {
    validate_outputs(c);
    FAIL() << "bead 102 taken";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "forces_at 102: outside the chain of 101 beads (1..N)");
  }
  try {
    read_output(c, "forces_at", "-4");
    FAIL() << "bead -4 taken";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "forces_at -4: outside the chain (beads count from 1)");
  }
}

}  // namespace
}  // namespace granular
