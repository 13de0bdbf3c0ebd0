// TwistedModeIpr ("--solver fast") against two independent references on the same chains:
// LapackModeIpr (dstevr, MRRR) and a dense Eigen::SelfAdjointEigenSolver (Householder + QR).
//
// What "agree" can mean here is set by conditioning, not by taste:
//  * A mode's eigenvector, hence its IPR, is determined by the double-precision matrix only to
//    about ε‖D‖/gap: its *relative gap* relgap_k = min(|ω²_k − ω²_{k±1}|) / max ω² decides.
//    Measured over the default ipr-map job's chains (2730 chains, Anderson, ξ = 0.1…1,
//    q = 0.2/0.5/0.8), the two *references* differ from each other by up to
//    1.1e-11 for relgap ∈ [1e-4, 1e-3), 1.0e-10 for [1e-5, 1e-4), 1.2e-9 for [1e-6, 1e-5), and
//    max |ΔIPR|·relgap ≈ 3.5e-15 throughout [1e-10, 1e-4). So the tight-cluster criterion of
//    these tests is relgap < 1e-4: outside it IPRs must agree to 1e-10 (the brief's tolerance);
//    for 1e-10 ≤ relgap < 1e-4 they must agree to 1e-14/relgap (as well as the matrix allows);
//    below 1e-10 (light beads isolated among heavy ones at small ξ: splittings down to 1e-16)
//    any orthonormal basis of the cluster is as valid and IPRs are only checked to lie in (0, 1]
//    and, on an exactly degenerate constructed case, to be those of an orthonormal basis.
//    (The solver hands exactly these modes, relgap < TwistedIprConfig::cluster_gap = 1e-10, to
//    dstein; see twisted_ipr_solver.hpp.)
//  * Eigenvalues from any backward-stable method carry absolute errors ~ε‖D‖, so a mode with
//    ω² ≪ ‖D‖ has a relative error ~ε‖D‖/ω². At ξ = 0.1 the lowest ω² is ~1e-7‖D‖ and the two
//    references differ by 4.6e-11 in relative frequency there. Frequencies are therefore checked
//    to 1e-12 relative for modes with ω² ≥ 1e-3 max ω², and to |Δω²| ≤ 1e-13 max ω² for all.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

// GCC 12 with -march=native (AVX-512) reports a false -Wmaybe-uninitialized inside Eigen's
// vectorized dense kernels once inlined here; the library itself does not include them.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <Eigen/Eigenvalues>

#include "granular/error.hpp"
#include "granular/linear/detail/mode_ipr_solver.hpp"
#include "granular/linear/detail/twisted_ipr_solver.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/random_stream.hpp"

namespace granular {
namespace {

constexpr double ipr_tolerance = 1e-10;       // outside tight clusters
constexpr double cluster_relgap = 1e-4;       // tight cluster: relgap below this
constexpr double conditioned_relgap = 1e-10;  // below this: any basis
constexpr double conditioning_constant = 1e-14;
constexpr double freq_tolerance = 1e-12;  // relative, for ω² ≥ 1e-3 max ω²
constexpr double low_mode_fraction = 1e-3;
constexpr double omega2_abs_tolerance = 1e-13;  // |Δω²| / max ω², all modes

struct Solution {
  std::vector<double> omega2, ipr;
};

struct Reference {
  SymTridiagonal d;
  std::vector<double> s;  // m^{-1/2}
  Solution stevr;
};

Reference make_reference(const Chain& chain) {
  Reference r{dynamical_matrix(chain), inverse_sqrt_mass(chain.inverse_mass), {}};
  LapackModeIpr lapack(LapackDriver::stevr);
  lapack.solve(r.d, r.s, r.stevr.omega2, r.stevr.ipr);
  return r;
}

/// Eigen's dense solver on the reference's tridiagonal matrix scaled by its largest entry `scale`
/// (eigenvalues are then those of the matrix / scale).
Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> scaled_dense_solver(const Reference& r, double scale) {
  const Eigen::Index n = static_cast<Eigen::Index>(r.d.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) a(i, i) = r.d.diagonal[i] / scale;
  for (Eigen::Index i = 0; i + 1 < n; ++i) a(i, i + 1) = a(i + 1, i) = r.d.off_diagonal[i] / scale;
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a);
}

Solution dense_eigen(const Reference& r) {
  const Eigen::Index n = static_cast<Eigen::Index>(r.d.size());
  const double scale = r.d.max_abs();
  const auto es = scaled_dense_solver(r, scale);
  Solution out;
  for (Eigen::Index k = 0; k < n; ++k) {
    out.omega2.push_back(es.eigenvalues()[k] * scale);
    out.ipr.push_back(displacement_ipr(es.eigenvectors().col(k).data(), r.s.data(), r.d.size()));
  }
  return out;
}

/// Clusters of two modes (consecutive relgap < 1e-11, inside the solver's cluster_gap 1e-10, and ≥ 1e-6 from
/// every other mode so the pair's subspace is well determined): their most localized basis,
/// found independently of the solver — from the dense Eigen eigenvectors of the same subspace, by
/// a brute-force search over the rotation angle (2000-point grid, then golden section) of the
/// objective the solver maximizes, Σ_i (x_i⁴ + y_i⁴) over the displacements x = m^{-1/2} w. That
/// objective is c₀ + A cos(4θ − φ): one maximum up to swapping and signs, so the two IPRs it gives
/// are the cluster's, whatever basis a solver started from. Pairs with A below 1e-12 c₀ (no
/// preferred basis) are skipped. Returns (first mode index, sorted IPRs) per pair, and the IPRs in
/// the order of the localized vectors' Rayleigh quotients, which number the modes, with how far
/// apart those quotients are (relative to max|λ|; 0 when they are equal).
struct PairIpr {
  std::size_t first;
  double lo, hi;
  double lower_quotient, upper_quotient;  // the IPR of the vector with the lower Rayleigh quotient, the other's
  double quotient_separation;
};
std::vector<PairIpr> localized_pairs(const Reference& r) {
  const Eigen::Index n = static_cast<Eigen::Index>(r.d.size());
  const double scale = r.d.max_abs();
  const auto es = scaled_dense_solver(r, scale);
  const Eigen::VectorXd& w = es.eigenvalues();
  const double norm = std::max(std::fabs(w[0]), std::fabs(w[n - 1]));
  std::vector<PairIpr> out;
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    if ((w[k + 1] - w[k]) / norm >= 1e-11) continue;  // well inside the solver's cluster_gap 1e-10
    if (k > 0 && (w[k] - w[k - 1]) / norm < 1e-6) continue;
    if (k + 2 < n && (w[k + 2] - w[k + 1]) / norm < 1e-6) continue;
    std::vector<double> x(static_cast<std::size_t>(n)), y(x.size());
    for (Eigen::Index i = 0; i < n; ++i) {
      x[static_cast<std::size_t>(i)] = es.eigenvectors()(i, k) * r.s[static_cast<std::size_t>(i)];
      y[static_cast<std::size_t>(i)] = es.eigenvectors()(i, k + 1) * r.s[static_cast<std::size_t>(i)];
    }
    auto objective = [&](double t) {
      const double c = std::cos(t), sn = std::sin(t);
      double sum = 0;
      for (std::size_t i = 0; i < x.size(); ++i) {
        const double p = c * x[i] + sn * y[i], q = -sn * x[i] + c * y[i];
        sum += p * p * p * p + q * q * q * q;
      }
      return sum;
    };
    const double quarter = std::acos(-1.0) / 2;
    double best = 0, fmax = -1, fmin = INFINITY;
    for (int g = 0; g < 2000; ++g) {
      const double t = quarter * g / 2000, f = objective(t);
      if (f > fmax) fmax = f, best = t;
      fmin = std::min(fmin, f);
    }
    if (fmax - fmin < 1e-12 * fmax) continue;
    double lo = best - quarter / 2000, hi = best + quarter / 2000;
    const double phi = 0.5 * (std::sqrt(5.0) - 1);
    for (int it = 0; it < 80; ++it) {
      const double m1 = hi - phi * (hi - lo), m2 = lo + phi * (hi - lo);
      if (objective(m1) > objective(m2)) hi = m2;
      else lo = m1;
    }
    const double t = 0.5 * (lo + hi), c = std::cos(t), sn = std::sin(t);
    std::vector<double> p(x.size()), q(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      p[i] = (c * x[i] + sn * y[i]) / r.s[i];  // back to w: displacement_ipr applies m^{-1/2}
      q[i] = (-sn * x[i] + c * y[i]) / r.s[i];
    }
    const double ip = displacement_ipr(p.data(), r.s.data(), x.size());
    const double iq = displacement_ipr(q.data(), r.s.data(), x.size());
    // c w_k + s w_{k+1} has the quotient c² λ_k + s² λ_{k+1}: p's is the lower when c² > s²
    const bool p_lower = c * c > sn * sn;
    const double separation = std::fabs(c * c - sn * sn) * (w[k + 1] - w[k]) / norm;
    out.push_back({static_cast<std::size_t>(k), std::min(ip, iq), std::max(ip, iq), p_lower ? ip : iq,
                   p_lower ? iq : ip, separation});
  }
  return out;
}

/// The solver's IPRs of each isolated pair must be the localized pair's (a wrong rotation, or
/// none — any other basis of the pair — fails), and where the two vectors' Rayleigh quotients are
/// apart (by 1e-13 max|λ|, far above their rounding) in the quotients' order: the mode numbers.
/// Returns the number of pairs checked; `ordered` counts those whose order was checked too.
std::size_t check_pairs(const std::vector<double>& ipr, const Reference& r, const std::string& what,
                        std::size_t* ordered = nullptr) {
  std::size_t checked = 0;
  for (const PairIpr& pair : localized_pairs(r)) {
    const double a = std::min(ipr[pair.first], ipr[pair.first + 1]);
    const double b = std::max(ipr[pair.first], ipr[pair.first + 1]);
    EXPECT_NEAR(a, pair.lo, 1e-8) << what << " pair at mode " << pair.first + 1;
    EXPECT_NEAR(b, pair.hi, 1e-8) << what << " pair at mode " << pair.first + 1;
    if (pair.quotient_separation > 1e-13 && pair.hi - pair.lo > 1e-6) {
      EXPECT_NEAR(ipr[pair.first], pair.lower_quotient, 1e-8) << what << " pair at mode " << pair.first + 1;
      EXPECT_NEAR(ipr[pair.first + 1], pair.upper_quotient, 1e-8) << what << " pair at mode " << pair.first + 1;
      if (ordered) ++*ordered;
    }
    ++checked;
  }
  return checked;
}

/// relgap_k from a reference spectrum (ascending).
std::vector<double> relative_gaps(const std::vector<double>& w) {
  const std::size_t n = w.size();
  const double norm = std::max(std::fabs(w.front()), std::fabs(w.back()));
  std::vector<double> g(n, INFINITY);
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) g[k] = std::min(g[k], (w[k] - w[k - 1]) / norm);
    if (k + 1 < n) g[k] = std::min(g[k], (w[k + 1] - w[k]) / norm);
  }
  return g;
}

struct Tally {
  std::size_t checked_strict = 0, checked_conditioned = 0, clustered = 0;
  double worst_strict = 0, worst_conditioned = 0, worst_freq = 0, worst_abs = 0;
};

/// Compares `got` with `ref` under the rules in the file comment; `what` names the pair.
void compare(const Solution& got, const Solution& ref, const std::string& what, Tally& tally) {
  const std::size_t n = ref.omega2.size();
  ASSERT_EQ(got.omega2.size(), n) << what;
  ASSERT_EQ(got.ipr.size(), n) << what;
  const double norm = std::max(std::fabs(ref.omega2.front()), std::fabs(ref.omega2.back()));
  const auto gap = relative_gaps(ref.omega2);
  for (std::size_t k = 0; k < n; ++k) {
    const double dw = std::fabs(got.omega2[k] - ref.omega2[k]) / norm;
    tally.worst_abs = std::max(tally.worst_abs, dw);
    EXPECT_LE(dw, omega2_abs_tolerance) << what << " mode " << k + 1;
    if (ref.omega2[k] >= low_mode_fraction * norm) {
      const double f = std::sqrt(ref.omega2[k]);
      const double df = std::fabs(std::sqrt(got.omega2[k]) - f) / f;
      tally.worst_freq = std::max(tally.worst_freq, df);
      EXPECT_LE(df, freq_tolerance) << what << " mode " << k + 1;
    }
    EXPECT_GT(got.ipr[k], 0.0) << what << " mode " << k + 1;
    EXPECT_LE(got.ipr[k], 1.0) << what << " mode " << k + 1;
    const double dp = std::fabs(got.ipr[k] - ref.ipr[k]);
    if (gap[k] >= cluster_relgap) {
      ++tally.checked_strict;
      tally.worst_strict = std::max(tally.worst_strict, dp);
      EXPECT_LE(dp, ipr_tolerance) << what << " mode " << k + 1 << " relgap " << gap[k];
    } else if (gap[k] >= conditioned_relgap) {
      ++tally.checked_conditioned;
      tally.worst_conditioned = std::max(tally.worst_conditioned, dp * gap[k]);
      EXPECT_LE(dp, conditioning_constant / gap[k]) << what << " mode " << k + 1 << " relgap " << gap[k];
    } else {
      ++tally.clustered;
    }
  }
}

Solution solve(ModeIprSolver& solver, const Reference& r) {
  Solution out;
  solver.solve(r.d, r.s, out.omega2, out.ipr);
  return out;
}

const Disorder all_disorders[] = {Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2};

// Random chains of every disorder kind, ξ drawn uniformly in [0.1, 1], q ∈ {0.2, 0.5, 0.8}:
// the fast solver against dstevr and against a dense Eigen solve.
TEST(TwistedModeIpr, AgreesWithStevrAndDenseEigenOnRandomChains) {
  TwistedModeIpr fast;
  RandomStream xi_stream(2024, 7);
  Tally vs_stevr, vs_eigen;
  std::size_t chains = 0, pairs = 0, ordered = 0;
  for (Disorder disorder : all_disorders)
    for (double q : {0.2, 0.5, 0.8})
      for (std::uint64_t r = 0; r < 24; ++r) {
        const double xi = r == 0 ? 0.1 : (r == 1 ? 1.0 : 0.1 + 0.9 * xi_stream.uniform());
        const std::size_t n = r % 3 == 2 ? 101 : 100;  // odd N too
        const auto types = realization_configuration(disorder, q, n, 99, r);
        const Reference ref = make_reference(make_chain(radii_of(types, 4.76e-3, xi), 10.0));
        const Solution got = solve(fast, ref);
        const std::string what =
            to_string(disorder) + " q=" + std::to_string(q) + " xi=" + std::to_string(xi) + " r=" + std::to_string(r);
        compare(got, ref.stevr, "fast vs stevr, " + what, vs_stevr);
        compare(got, dense_eigen(ref), "fast vs Eigen, " + what, vs_eigen);
        pairs += check_pairs(got.ipr, ref, "fast, " + what, &ordered);
        ++chains;
      }
  EXPECT_EQ(fast.info().fallbacks, 0u);
  EXPECT_GT(fast.info().clusters, 0u) << "the sample should contain small-ξ clusters";
  EXPECT_GT(pairs, 0u) << "isolated degenerate pairs should have been checked against the localized basis";
  EXPECT_GT(ordered, 0u) << "some pairs should have had their numbering checked";
  std::printf("[ info ] isolated pairs checked against the independently localized basis: %zu (numbering: %zu)\n",
              pairs, ordered);
  EXPECT_GT(vs_stevr.checked_strict, 50u * chains);
  RecordProperty("worst_ipr_vs_stevr", std::to_string(vs_stevr.worst_strict));
  RecordProperty("worst_ipr_vs_eigen", std::to_string(vs_eigen.worst_strict));
  std::printf(
      "[ info ] %zu chains; IPR modes checked to 1e-10: %zu, to 1e-14/relgap: %zu, in clusters: %zu\n"
      "[ info ] worst |dIPR| vs stevr %.3g, vs Eigen %.3g; worst |dIPR|*relgap %.3g / %.3g;\n"
      "[ info ] worst rel. freq %.3g / %.3g; worst |dw2|/max w2 %.3g / %.3g\n",
      chains, vs_stevr.checked_strict, vs_stevr.checked_conditioned, vs_stevr.clustered, vs_stevr.worst_strict,
      vs_eigen.worst_strict, vs_stevr.worst_conditioned, vs_eigen.worst_conditioned, vs_stevr.worst_freq,
      vs_eigen.worst_freq, vs_stevr.worst_abs, vs_eigen.worst_abs);
}

// The default ipr-map grid (Anderson, ξ = 0.1:1:0.01, q = 0.2/0.5/0.8) against dstevr, a few
// realizations per cell: every (q, ξ) the tool visits is exercised.
TEST(TwistedModeIpr, AgreesWithStevrOnTheDefaultIprMapGrid) {
  TwistedModeIpr fast;
  Tally tally;
  for (double q : {0.2, 0.5, 0.8})
    for (int step = 0; step <= 90; ++step) {
      const double xi = 0.1 + 0.01 * step;
      for (std::uint64_t r = 0; r < 3; ++r) {
        const auto types = realization_configuration(Disorder::anderson, q, 100, 1, r);
        const Reference ref = make_reference(make_chain(radii_of(types, 4.76e-3, xi), 10.0));
        compare(solve(fast, ref), ref.stevr,
                "q=" + std::to_string(q) + " xi=" + std::to_string(xi) + " r=" + std::to_string(r), tally);
      }
    }
  EXPECT_EQ(fast.info().fallbacks, 0u);
  std::printf("[ info ] grid: worst |dIPR| %.3g on %zu modes (relgap >= 1e-4), worst |dIPR|*relgap %.3g\n",
              tally.worst_strict, tally.checked_strict, tally.worst_conditioned);
}

// Chains ten times the default length (N = 997: no multiple of the lane count, so every chain
// ends with a partly filled batch of twisted factorizations) against dstevd, under the same rules.
TEST(TwistedModeIpr, AgreesWithStevdOnLongChains) {
  TwistedModeIpr fast;
  Tally tally;
  std::size_t chains = 0;
  for (double q : {0.2, 0.8})
    for (double xi : {0.1, 0.35, 0.7, 1.0}) {
      const auto types = realization_configuration(Disorder::anderson, q, 997, 5, chains);
      const Chain chain = make_chain(radii_of(types, 4.76e-3, xi), 10.0);
      const SymTridiagonal d = dynamical_matrix(chain);
      const std::vector<double> s = inverse_sqrt_mass(chain.inverse_mass);
      Solution stevd;
      LapackModeIpr(LapackDriver::stevd).solve(d, s, stevd.omega2, stevd.ipr);
      Solution got;
      fast.solve(d, s, got.omega2, got.ipr);
      compare(got, stevd, "N=997 q=" + std::to_string(q) + " xi=" + std::to_string(xi), tally);
      ++chains;
    }
  EXPECT_EQ(fast.info().fallbacks, 0u);
  EXPECT_GT(tally.checked_strict, 100u * chains);
  std::printf(
      "[ info ] N=997: worst |dIPR| %.3g on %zu modes (relgap >= 1e-4), worst |dIPR|*relgap %.3g, in clusters %zu\n",
      tally.worst_strict, tally.checked_strict, tally.worst_conditioned, tally.clustered);
}

// Two identical chains joined by a vanishing bond: every eigenvalue is exactly double, the
// cluster case in its purest form. Any orthonormal basis {c a + s b, −s a + c b} of a pair (a, b
// the mode on either copy) gives both vectors the IPR (c⁴ + s⁴) P, P the single copy's IPR, in
// [P/2, P]; the solver's localized basis must reach P (dstein alone gave anything in between).
TEST(TwistedModeIpr, ExactlyDegeneratePairsGetAnOrthonormalBasis) {
  const auto types = realization_configuration(Disorder::anderson, 0.8, 40, 3, 0);
  const Chain one = make_chain(radii_of(types, 4.76e-3, 0.3), 10.0);
  const Reference half = make_reference(one);
  for (double coupling : {0.0, 1e-300, 1e-30}) {
    SymTridiagonal d;
    d.diagonal = half.d.diagonal;
    d.diagonal.insert(d.diagonal.end(), half.d.diagonal.begin(), half.d.diagonal.end());
    d.off_diagonal = half.d.off_diagonal;
    d.off_diagonal.push_back(-coupling);
    d.off_diagonal.insert(d.off_diagonal.end(), half.d.off_diagonal.begin(), half.d.off_diagonal.end());
    std::vector<double> s = half.s;
    s.insert(s.end(), half.s.begin(), half.s.end());
    TwistedModeIpr fast;
    std::vector<double> w2, p;
    fast.solve(d, s, w2, p);
    ASSERT_EQ(w2.size(), 80u);
    EXPECT_EQ(fast.info().fallbacks, 0u);
    EXPECT_EQ(fast.info().cluster_modes, 80u) << "every mode is in a pair";
    for (std::size_t k = 0; k < 40; ++k) {
      const double big = half.stevr.ipr[k];
      EXPECT_NEAR(w2[2 * k] / half.stevr.omega2[k], 1.0, 1e-12) << "pair " << k;
      EXPECT_NEAR(w2[2 * k + 1] / half.stevr.omega2[k], 1.0, 1e-12) << "pair " << k;
      EXPECT_NEAR(p[2 * k], p[2 * k + 1], 1e-10) << "pair " << k << " coupling " << coupling;
      // The cluster basis is rotated to the most localized one: each vector of a pair sits on
      // one copy, so its IPR is (at least, if neighbouring pairs mix too) the single copy's.
      EXPECT_GE(p[2 * k], big - 1e-10) << "pair " << k;
      EXPECT_LE(p[2 * k], 1.0) << "pair " << k;
    }
  }
}

// The guard: an impossible residual limit makes every chain fall back to dstevr, whose result
// is then returned unchanged.
TEST(TwistedModeIpr, FallsBackToLapackWhenAGuardTrips) {
  const auto types = realization_configuration(Disorder::rdm2, 0.5, 100, 5, 1);
  const Reference ref = make_reference(make_chain(radii_of(types, 4.76e-3, 0.6), 10.0));
  TwistedIprConfig config;
  config.max_residual = 1e-300;
  TwistedModeIpr strict(config);
  const Solution got = solve(strict, ref);
  EXPECT_EQ(strict.info().fallbacks, 1u);
  EXPECT_EQ(got.omega2, ref.stevr.omega2);
  EXPECT_EQ(got.ipr, ref.stevr.ipr);
}

TEST(TwistedModeIpr, RejectsNonFiniteMatricesAndBadConfig) {
  TwistedModeIpr fast;
  SymTridiagonal d{{2.0, NAN, 2.0}, {-1.0, -1.0}};
  std::vector<double> s{1, 1, 1}, w2, p;
  EXPECT_THROW(fast.solve(d, s, w2, p), NumericalError);
  EXPECT_THROW(fast.solve(SymTridiagonal{{2.0, 2.0}, {-1.0}}, s, w2, p), InvalidInput);  // s has 3 entries
  TwistedIprConfig bad;
  bad.cluster_gap = -1;
  EXPECT_THROW(TwistedModeIpr{bad}, InvalidInput);
}

// One instance, reused across sizes and chains, gives what a fresh instance gives.
TEST(TwistedModeIpr, ReusedWorkspaceGivesIdenticalResults) {
  TwistedModeIpr reused;
  for (std::size_t n : {100u, 37u, 160u, 100u}) {
    const auto types = realization_configuration(Disorder::anderson, 0.5, n, 11, n);
    const Reference ref = make_reference(make_chain(radii_of(types, 4.76e-3, 0.4), 10.0));
    TwistedModeIpr fresh;
    const Solution a = solve(reused, ref), b = solve(fresh, ref);
    EXPECT_EQ(a.omega2, b.omega2) << n;
    EXPECT_EQ(a.ipr, b.ipr) << n;
  }
}

// solve_batch runs the QL iterations of its chains in vector lanes (more chains than lanes: lanes
// take new chains); every chain's result must be bit-identical to solving it alone (ipr-map's
// thread-count independence rests on this).
TEST(TwistedModeIpr, BatchedSolvesEqualSingleSolves) {
  std::vector<Reference> refs;
  for (std::uint64_t r = 0; r < 41; ++r) {
    const std::size_t n = r == 4 ? 57 : r == 30 ? 2 : 100;  // shorter chains inside a batch
    const auto types = realization_configuration(r % 2 ? Disorder::anderson : Disorder::rdm1, 0.8, n, 13, r);
    refs.push_back(make_reference(make_chain(radii_of(types, 4.76e-3, 0.1 + 0.1 * static_cast<double>(r % 10)), 10.0)));
  }
  // and two copies of one chain joined by a vanishing bond: every mode in an exactly degenerate pair
  const Reference half = refs[7];
  Reference doubled = half;
  doubled.d.diagonal.insert(doubled.d.diagonal.end(), half.d.diagonal.begin(), half.d.diagonal.end());
  doubled.d.off_diagonal.push_back(0.0);
  doubled.d.off_diagonal.insert(doubled.d.off_diagonal.end(), half.d.off_diagonal.begin(), half.d.off_diagonal.end());
  doubled.s.insert(doubled.s.end(), half.s.begin(), half.s.end());
  refs.insert(refs.begin() + 20, doubled);
  std::vector<Solution> batched(refs.size());
  std::vector<ModeIprTask> tasks;
  for (std::size_t i = 0; i < refs.size(); ++i)
    tasks.push_back({&refs[i].d, &refs[i].s, &batched[i].omega2, &batched[i].ipr});
  TwistedModeIpr batch_solver, single_solver;
  batch_solver.solve_batch(tasks);
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const Solution single = solve(single_solver, refs[i]);
    EXPECT_EQ(batched[i].omega2, single.omega2) << "chain " << i;
    EXPECT_EQ(batched[i].ipr, single.ipr) << "chain " << i;
  }
  EXPECT_EQ(batch_solver.info().solves, refs.size());
  EXPECT_GE(batch_solver.info().cluster_modes, 2 * half.d.size());  // the pairs went through clusters
  EXPECT_EQ(batch_solver.info().fallbacks, 0u);
}

TEST(TwistedModeIpr, IsRegisteredAsFast) {
  auto solver = make_mode_ipr_solver("fast");
  EXPECT_NE(dynamic_cast<TwistedModeIpr*>(solver.get()), nullptr);
  EXPECT_THROW(make_mode_ipr_solver("fastest"), InvalidInput);
}

}  // namespace
}  // namespace granular
