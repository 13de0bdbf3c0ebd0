// twisted_lanes (the vectorized twisted factorizations of TwistedModeIpr) against its one-shift
// scalar reference twisted_one: every lane must give the same |γ_r|, twist and sums bit for bit,
// on chains whose spectra are spread, clustered (small ξ: light beads isolated among heavy ones,
// splittings down to 1e-16) and exactly degenerate, at shifts on eigenvalues, between them, on
// diagonal entries (exact zero pivots) and repeated across lanes, for N that is no multiple of
// the lane count (down to 2). A lane that takes its own twist, stops at its own negligible
// component or crosses a node differently from the scalar path fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "granular/linear/detail/mode_ipr_solver.hpp"
#include "granular/linear/detail/twisted_lanes.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/random_stream.hpp"

namespace granular {
namespace {

constexpr std::size_t twisted_lanes_width = detail::twisted_lane_count;

/// T / max|T| (as the solver scales it), m^{-1/2} / max, and the scaled eigenvalues (ascending).
struct TwistedLanesMatrix {
  std::vector<double> d, e, mass, lambda;
};

TwistedLanesMatrix twisted_lanes_matrix(const SymTridiagonal& t, const std::vector<double>& s) {
  TwistedLanesMatrix out;
  const double scale = t.max_abs(), smax = *std::max_element(s.begin(), s.end());
  for (double x : t.diagonal) out.d.push_back(x / scale);
  for (double x : t.off_diagonal) out.e.push_back(x / scale);
  for (double x : s) out.mass.push_back(x / smax);
  std::vector<double> w2, ipr;
  LapackModeIpr(LapackDriver::stevd).solve(t, s, w2, ipr);
  for (double x : w2) out.lambda.push_back(x / scale);
  return out;
}

/// Runs `shifts` through twisted_lanes in batches of `lanes` (the last one padded by repeating
/// its last shift, as the solver does) and compares every lane with twisted_one.
std::size_t twisted_lanes_check(const TwistedLanesMatrix& t, const std::vector<double>& shifts, const std::string& what) {
  const std::size_t n = t.d.size();
  detail::TwistedLaneWork work;
  std::vector<double> scalar_work;
  std::size_t checked = 0;
  for (std::size_t b = 0; b < shifts.size(); b += twisted_lanes_width) {
    double sigma[twisted_lanes_width];
    for (std::size_t l = 0; l < twisted_lanes_width; ++l) sigma[l] = shifts[std::min(b + l, shifts.size() - 1)];
    detail::TwistedSums got[twisted_lanes_width];
    detail::twisted_lanes(t.d.data(), t.e.data(), t.mass.data(), n, sigma, work, got);
    for (std::size_t l = 0; l < twisted_lanes_width; ++l) {
      const detail::TwistedSums want =
          detail::twisted_one(t.d.data(), t.e.data(), t.mass.data(), n, sigma[l], scalar_work);
      const std::string where = what + " shift " + std::to_string(b + l) + " = " + std::to_string(sigma[l]);
      EXPECT_EQ(got[l].twist, want.twist) << where;
      EXPECT_EQ(got[l].gamma, want.gamma) << where;
      EXPECT_EQ(got[l].z2, want.z2) << where;
      EXPECT_EQ(got[l].v2, want.v2) << where;
      EXPECT_EQ(got[l].v4, want.v4) << where;
      ++checked;
    }
  }
  return checked;
}

/// Eigenvalues, midpoints between neighbours, diagonal entries (zero pivots) and a repeated shift.
std::vector<double> twisted_lanes_shifts(const TwistedLanesMatrix& t) {
  std::vector<double> s = t.lambda;
  for (std::size_t k = 0; k + 1 < t.lambda.size(); k += 3) s.push_back(0.5 * (t.lambda[k] + t.lambda[k + 1]));
  for (std::size_t i = 0; i < t.d.size(); i += 7) s.push_back(t.d[i]);
  s.push_back(t.lambda.front());
  return s;
}

TEST(TwistedLanes, EveryLaneEqualsTheScalarFactorizationOnRandomChains) {
  RandomStream xi_stream(77, 3);
  std::size_t checked = 0;
  for (Disorder disorder : {Disorder::anderson, Disorder::rdm1, Disorder::rdm2})
    for (std::size_t n : {2u, 3u, 17u, 100u, 257u, 1001u})
      for (std::uint64_t r = 0; r < 2; ++r) {
        const double xi = r == 0 ? 0.1 : 0.1 + 0.9 * xi_stream.uniform();  // ξ = 0.1: clustered spectra
        const auto types = realization_configuration(disorder, 0.5, n, 21, r);
        const Chain chain = make_chain(radii_of(types, 4.76e-3, xi), 10.0);
        const TwistedLanesMatrix t =
            twisted_lanes_matrix(dynamical_matrix(chain), inverse_sqrt_mass(chain.inverse_mass));
        checked += twisted_lanes_check(t, twisted_lanes_shifts(t),
                                       to_string(disorder) + " N=" + std::to_string(n) + " xi=" + std::to_string(xi));
      }
  EXPECT_GT(checked, 10000u);
}

// Two identical chains joined by a vanishing bond: every eigenvalue is double and each
// eigenvector lives on one copy, so z crosses an exact node or stops in the middle.
TEST(TwistedLanes, EveryLaneEqualsTheScalarFactorizationOnDegenerateChains) {
  const auto types = realization_configuration(Disorder::anderson, 0.8, 45, 3, 0);
  const Chain one = make_chain(radii_of(types, 4.76e-3, 0.3), 10.0);
  const SymTridiagonal half = dynamical_matrix(one);
  const std::vector<double> s_half = inverse_sqrt_mass(one.inverse_mass);
  for (double coupling : {0.0, 1e-300, 1e-30, 1e-8}) {
    SymTridiagonal d;
    d.diagonal = half.diagonal;
    d.diagonal.insert(d.diagonal.end(), half.diagonal.begin(), half.diagonal.end());
    d.off_diagonal = half.off_diagonal;
    d.off_diagonal.push_back(-coupling);
    d.off_diagonal.insert(d.off_diagonal.end(), half.off_diagonal.begin(), half.off_diagonal.end());
    std::vector<double> s = s_half;
    s.insert(s.end(), s_half.begin(), s_half.end());
    const TwistedLanesMatrix t = twisted_lanes_matrix(d, s);
    twisted_lanes_check(t, twisted_lanes_shifts(t), "coupling " + std::to_string(coupling));
  }
}

}  // namespace
}  // namespace granular
