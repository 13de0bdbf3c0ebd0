// The mode IPR's mass weighting (docs/physics.md, "The linear spectrum": P⁻¹ of the displacements v = M^{-1/2} w, not of the
// eigenvector w of the symmetric matrix) on a two-mass chain diagonalized by hand, where the
// weighted and unweighted IPRs differ by a known factor.
#include "granular/linear/mode_ipr.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace granular {
namespace {

// Two beads, masses m1 and m2 = m1/8 (ξ = 1/2: m ∝ R³), joined by one spring B, free ends:
// D = M^{-1/2} K M^{-1/2} = B [[1/m1, −1/√(m1 m2)], [−1/√(m1 m2), 1/m2]].
// Its eigenvectors, by hand: ω = 0 with w ∝ (√m1, √m2) (D w = B(√m1/m1 − √m2/√(m1 m2), …) = 0),
// and ω² = B (1/m1 + 1/m2) with w ∝ (√m2, −√m1), orthogonal to it.
// Displacements v = M^{-1/2} w: the rigid translation v ∝ (1, 1), IPR = 2/4 = 1/2; the optical mode
// v ∝ (√m2/√m1, −√m1/√m2) ∝ (1, −m1/m2) = (1, −8), IPR = (1 + 8⁴)/(1 + 8²)² = 4097/4225.
// Unweighted (of w), both modes: (m1² + m2²)/(m1 + m2)² = (64 + 1)/81 = 65/81.
TEST(ModeIpr, MassWeightingOnATwoMassChain) {
  const double m1 = 8.0, m2 = 1.0, b = 3.0;
  const std::vector<double> inverse_mass{1 / m1, 1 / m2};
  const std::vector<double> s = inverse_sqrt_mass(inverse_mass);
  ASSERT_DOUBLE_EQ(s[0], 1 / std::sqrt(m1));
  const double acoustic[2] = {std::sqrt(m1), std::sqrt(m2)};
  const double optical[2] = {std::sqrt(m2), -std::sqrt(m1)};
  // They are eigenvectors of D (checked, not assumed): D w = λ w.
  const double d11 = b / m1, d12 = -b / std::sqrt(m1 * m2), d22 = b / m2;
  EXPECT_NEAR(d11 * acoustic[0] + d12 * acoustic[1], 0.0, 1e-12);
  EXPECT_NEAR(d12 * acoustic[0] + d22 * acoustic[1], 0.0, 1e-12);
  const double lambda = b * (1 / m1 + 1 / m2);
  EXPECT_NEAR(d11 * optical[0] + d12 * optical[1], lambda * optical[0], 1e-12);
  EXPECT_NEAR(d12 * optical[0] + d22 * optical[1], lambda * optical[1], 1e-12);

  EXPECT_NEAR(displacement_ipr(acoustic, s.data(), 2), 0.5, 1e-15);
  EXPECT_NEAR(displacement_ipr(optical, s.data(), 2), 4097.0 / 4225.0, 1e-15);
  // The wrong (unweighted) IPR would be 65/81 for both: unit weights give it.
  const std::vector<double> ones{1.0, 1.0};
  EXPECT_NEAR(displacement_ipr(acoustic, ones.data(), 2), 65.0 / 81.0, 1e-15);
  EXPECT_NEAR(displacement_ipr(optical, ones.data(), 2), 65.0 / 81.0, 1e-15);
  // Scale-free in w and in the weights (any common factor cancels).
  const double scaled[2] = {-7 * optical[0], -7 * optical[1]};
  const std::vector<double> s3{3 * s[0], 3 * s[1]};
  EXPECT_NEAR(displacement_ipr(scaled, s3.data(), 2), 4097.0 / 4225.0, 1e-15);
}

}  // namespace
}  // namespace granular
