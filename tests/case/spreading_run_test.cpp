// run_spreading (case/spreading_run.hpp) against spread() with the same observers: it only packs
// what they measured.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/dynamics_fixtures.hpp"
#include "granular/case/spreading_run.hpp"
#include "granular/dynamics/initial_conditions.hpp"

namespace granular {
namespace {

TEST(SpreadingRun, PacksWhatTheObserversMeasured) {
  const Chain chain = fixtures::anderson(121, 10.0);
  const State initial = displacement_kick(chain, 60, 1e-7);
  SpreadingRunConfig c;
  c.integration.duration = 2e-4;
  c.spread.samples = 30;
  c.spread.dense = {1e-4, 2e-4, 1e-5};
  c.spread.site = 60;
  c.forces.sites = {50, 70};
  c.forces.samples = 21;
  c.energy_map = EnergyMapObserver::Settings{11, 5};
  c.spectrum = SpectralDensityObserver::Settings{.samples = 50};
  const SpreadingResult r = run_spreading(chain, initial, c);

  EnergySpreadObserver spread(c.spread);
  ForceObserver forces(c.forces);
  EnergyMapObserver map(*c.energy_map);
  SpectralDensityObserver spectrum(*c.spectrum);
  FinalStateObserver final_state;
  granular::spread(chain, initial, integration_config(c), final_state, spectrum, map, forces, spread);
  EXPECT_EQ(r.t, spread.t);
  EXPECT_EQ(r.m2, spread.m2);
  EXPECT_EQ(r.m2_centroid, spread.m2_centroid);
  EXPECT_EQ(r.ipr, spread.ipr);
  EXPECT_EQ(r.energy_error, spread.energy_error);
  EXPECT_EQ(r.forces, forces.forces);
  EXPECT_EQ(r.map_energy, map.energy);
  EXPECT_EQ(r.spectrum, spectrum.density);
  EXPECT_EQ(r.final_energy, final_state.energy);
  std::vector<double> t;
  for (std::uint64_t s : sample_steps(c)) t.push_back(static_cast<double>(s) * c.integration.time_step);
  EXPECT_EQ(r.t, t);
}

}  // namespace
}  // namespace granular
