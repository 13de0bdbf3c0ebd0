// The outputs of a spreading run, chosen once for the tool and Python: beads counted from 1 inside
// the chain, every sampling count at least 2 (the stride at least 1), displacement or velocity
// spectra; each refusal names the choice, and good choices fill the case's observers.
#include "granular/study/spreading_output_choices.hpp"

#include <gtest/gtest.h>

#include <string>

#include "granular/error.hpp"

namespace granular {
namespace {

TransportCase outputs_case() {
  TransportCase c;
  c.chain.N = 101;
  return c;
}

/// The parameter `o` is refused for, or "" when it is taken.
std::string outputs_refused(const SpreadingOutputChoices& o) {
  TransportCase c = outputs_case();
  try {
    apply(o, c);
  } catch (const InvalidInput& e) {
    return e.parameter();
  }
  return "";
}

TEST(SpreadingOutputChoices, GoodChoicesFillTheObservers) {
  TransportCase c = outputs_case();
  apply(SpreadingOutputChoices{}, c);  // the defaults ask for nothing
  EXPECT_TRUE(c.dynamics.forces.sites.empty());
  EXPECT_FALSE(c.dynamics.energy_map);
  EXPECT_FALSE(c.dynamics.spectrum);

  const SpreadingOutputChoices o{.forces_at = {1, 51, 101},
                                 .force_samples = 20,
                                 .energy_map = true,
                                 .map_samples = 10,
                                 .map_stride = 3,
                                 .spectral_density = true,
                                 .spectrum_samples = 64,
                                 .spectrum_of = "velocity"};
  apply(o, c);
  EXPECT_EQ(c.dynamics.forces.sites, (std::vector<std::size_t>{0, 50, 100}));  // 0-based
  EXPECT_EQ(c.dynamics.forces.samples, 20u);
  ASSERT_TRUE(c.dynamics.energy_map);
  EXPECT_EQ(c.dynamics.energy_map->samples, 10u);
  EXPECT_EQ(c.dynamics.energy_map->stride, 3u);
  ASSERT_TRUE(c.dynamics.spectrum);
  EXPECT_EQ(c.dynamics.spectrum->samples, 64u);
  EXPECT_EQ(c.dynamics.spectrum->source, SpectrumSource::velocity);

  apply(SpreadingOutputChoices{.forces_at = {7}}, c);  // applied again: replaced, not added to
  EXPECT_EQ(c.dynamics.forces.sites, (std::vector<std::size_t>{6}));
  EXPECT_FALSE(c.dynamics.energy_map);
  EXPECT_FALSE(c.dynamics.spectrum);
}

TEST(SpreadingOutputChoices, ABadChoiceIsRefusedByName) {
  EXPECT_EQ(outputs_refused({.forces_at = {0}}), "forces_at");
  EXPECT_EQ(outputs_refused({.forces_at = {50, 102}}), "forces_at");
  EXPECT_EQ(outputs_refused({.forces_at = {101}}), "");
  EXPECT_EQ(outputs_refused({.force_samples = 1}), "force_samples");
  EXPECT_EQ(outputs_refused({.map_samples = 1}), "map_samples");  // refused whether or not a map is asked
  EXPECT_EQ(outputs_refused({.energy_map = true, .map_samples = 1}), "map_samples");
  EXPECT_EQ(outputs_refused({.energy_map = true, .map_samples = 2}), "");
  EXPECT_EQ(outputs_refused({.map_samples = 2}), "map_samples");  // takes effect only with a map: not ignored
  EXPECT_EQ(outputs_refused({.map_samples = 100000001}), "map_samples");
  EXPECT_EQ(outputs_refused({.map_stride = 0}), "map_stride");
  EXPECT_EQ(outputs_refused({.spectrum_samples = -3}), "spectrum_samples");
  EXPECT_EQ(outputs_refused({.spectrum_of = "force"}), "spectrum_of");
}

TEST(SpreadingOutputChoices, TheMessageSaysWhereTheChainIs) {
  TransportCase c = outputs_case();
  try {
    apply(SpreadingOutputChoices{.forces_at = {0}}, c);
    FAIL() << "bead 0 taken";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "forces_at 0: outside the chain of 101 beads (1..N)");
  }
}

}  // namespace
}  // namespace granular
