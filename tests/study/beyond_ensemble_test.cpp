// Beyond the paper in the ensemble: the mean X1(t) of the tangent map and damped runs, bit-identical for
// any thread count, and the ensemble X1 equals the mean of single runs.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "granular/case/spreading_run.hpp"
#include "granular/error.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"
#include "granular/study/transport_study.hpp"

namespace granular {
namespace {

TransportCase lyapunov_case() {
  TransportCase c;
  c.chain.draw().disorder = Disorder::anderson;
  c.chain.N = 201;
  c.site = 101;
  c.chain.F0 = 0.1;
  c.realizations = 4;
  c.profile_realizations = 2;
  c.dynamics.integration.duration = 1e-3;
  c.dynamics.spread.samples = 30;
  c.dynamics.integration.lyapunov.enabled = true;
  c.fit_begin = 4e-4;
  c.fit_end = 1e-3;
  c.criterion.t_start = 4e-4;
  return c;
}

TEST(BeyondEnsemble, MeanLyapunovExponentIsBitIdenticalForOneAndTwoThreads) {
  const TransportCase c = lyapunov_case();
  const TransportSummary one = run_transport_study(c, {1, "", false, nullptr});
  const TransportSummary two = run_transport_study(c, {2, "", false, nullptr});
  ASSERT_EQ(one.mle.mean.size(), one.t.size());
  EXPECT_EQ(one.mle.mean, two.mle.mean);
  EXPECT_EQ(one.m2.mean, two.m2.mean);
  EXPECT_EQ(one.profile.mean.size(), 201u);  // the profile still sits after the X1 series
  // The ensemble's X1 is the mean of the single runs'.
  double sum = 0;
  for (std::uint64_t r = 0; r < c.realizations; ++r) {
    const Chain chain = make_chain(radii_of(realization_configuration(c.chain.draw().disorder, c.chain.draw().q,
                                                                      c.chain.N, c.chain.seed, r),
                                            c.chain.R1, c.chain.xi()),
                                   c.chain.F0);
    sum += run_spreading(chain, kick(c, chain).initial, spreading_config(c)).mle.back();
  }
  EXPECT_NEAR(one.mle.mean.back(), sum / 4, 1e-12 * std::abs(sum));
  EXPECT_GT(one.mle.mean.back(), 0.0);
}

TEST(BeyondEnsemble, DampedEnsembleIsBitIdenticalForOneAndTwoThreads) {
  TransportCase c = lyapunov_case();
  c.dynamics.integration.lyapunov.enabled = false;
  c.dynamics.integration.damping = {1e-3, 1e-6};
  const TransportSummary one = run_transport_study(c, {1, "", false, nullptr});
  const TransportSummary two = run_transport_study(c, {2, "", false, nullptr});
  EXPECT_EQ(one.m2.mean, two.m2.mean);
  EXPECT_TRUE(one.mle.mean.empty());
  // H + dissipated = H0 in every realization, to the accuracy of the conservative scheme on the
  // same case (contacts open at F0 = 0.1 N: SABA2C at τ = 1 µs is far from its smooth-case level).
  c.dynamics.integration.damping = {};
  const TransportSummary conservative = run_transport_study(c, {1, "", false, nullptr});
  std::printf("  max |H + dissipated - H0| / H0 = %.2e; conservative |H - H0| / H0 = %.2e\n", one.max_energy_error,
              conservative.max_energy_error);
  EXPECT_LT(one.max_energy_error, 3 * conservative.max_energy_error);
}

TEST(BeyondEnsemble, TangentMapAndDampingTogetherAreRejected) {
  TransportCase c = lyapunov_case();
  c.dynamics.integration.damping = {1e-3, 0};
  EXPECT_THROW(validate(c.dynamics, c.chain.N), InvalidInput);
}

}  // namespace
}  // namespace granular
