#pragma once
// The drift–kick kernels of blocked_kernels.hpp for W chains of one length side by side, one chain
// per vector lane (parallel/detail/vector_lanes.hpp). Arrays are interleaved: element i of lane l
// is at [i · W + l]. Each lane has its own active window [lo_l, hi_l): the loops run over the
// union of the windows, and a lane's beads outside its own window are left exactly as they are,
// its accelerations there read as 0 — what the one-chain kernels do by not visiting them. Every
// lane therefore gets the bits the one-chain kernel gives its chain (the force laws' formulas are
// written once for both, force_law.hpp; no FMA contraction in this library), which
// tests/lanes/lane_propagator_test.cpp checks for every scheme, law and window.
//
// Unlike the one-chain kernels these run fused, bond and bead in one pass: a lane's previous bond
// force stays in a register instead of being stored and read back, which in one chain would read
// a vector's neighbour element right after storing it (blocked_kernels.hpp).
#include <cstddef>

#include "granular/dynamics/detail/window_rule.hpp"
#include "granular/dynamics/force_law.hpp"
#include "granular/parallel/detail/vector_lanes.hpp"

namespace granular {

template <>
struct ValueMath<detail::lanes::V> {
  static detail::lanes::V root(const detail::lanes::V& x) { return detail::lanes::root(x); }
  static detail::lanes::V positive_part(const detail::lanes::V& x) { return detail::lanes::positive_part(x); }
  static detail::lanes::V at_least(const detail::lanes::V& x, double low) {  // std::max(x, low) in every lane
    const detail::lanes::V floor = detail::lanes::V{} + low;
    return x < floor ? floor : x;
  }
};

namespace detail::lane_kernels {

using lanes::load;
using lanes::M;
using lanes::select;
using lanes::store;
using lanes::V;
using lanes::W;

/// The bond laws of W chains, interleaved: Hertz's (contact, overlap, rest) or the polynomial's
/// (c1, c2, c3) per bond; k_n and q_n of the on-site springs per bead (null when none).
struct LaneLaw {
  const double* __restrict p1;
  const double* __restrict p2;
  const double* __restrict p3;
  const double* __restrict onsite;
  const double* __restrict onsite_quartic;
};

template <bool hertz>
inline V bond_force(const LaneLaw& law, std::size_t k, const V& x) {
  const std::size_t at = k * W;
  if constexpr (hertz) return hertz_force_of<V>(load(law.p1 + at), load(law.p2 + at), load(law.p3 + at), x);
  else return polynomial_force_of<V>(load(law.p1 + at), load(law.p2 + at), load(law.p3 + at), x);
}

template <bool hertz>
inline void bond_force_stiffness(const LaneLaw& law, std::size_t k, const V& x, V& f, V& stiff) {
  const std::size_t at = k * W;
  const V p1 = load(law.p1 + at), p2 = load(law.p2 + at), p3 = load(law.p3 + at);
  if constexpr (hertz) {
    hertz_force_stiffness_of<V>(p1, p2, p3, x, f, stiff);
  } else {
    f = polynomial_force_of<V>(p1, p2, p3, x);
    stiff = polynomial_stiffness_of<V>(p1, p2, p3, x);
  }
}

template <bool quartic>
inline V onsite_restoring_lanes(const LaneLaw& law, std::size_t bead, const V& u) {
  return onsite_restoring_of<quartic, V>(load(law.onsite + bead * W),
                                         quartic ? load(law.onsite_quartic + bead * W) : V{}, u);
}
template <bool quartic>
inline V onsite_hessian_lanes(const LaneLaw& law, std::size_t bead, const V& u) {
  return onsite_hessian_of<quartic, V>(load(law.onsite + bead * W), quartic ? load(law.onsite_quartic + bead * W) : V{},
                                       u);
}

/// The lanes whose window holds bead `i`.
inline M inside(std::size_t i, const M& lo, const M& hi) {
  const M at = M{} + static_cast<long>(i);
  return (at >= lo) & (at < hi);
}

// v += h F/m, then u += d v, on beads [LO, HI) (the union of the windows lo, hi). u is padded as
// in blocked_kernels.hpp: u[(k)·W + l] is bead k−1 of lane l, rows 0 and N+1 the walls.
template <bool hertz, bool grounded, bool quartic>
void kick_and_drift(const LaneLaw& law, double* __restrict u, double* __restrict v, const double* __restrict im,
                    const M& lo, const M& hi, std::size_t LO, std::size_t HI, double h, double d) {
  V previous = bond_force<hertz>(law, LO, load(u + LO * W) - load(u + (LO + 1) * W));
  for (std::size_t k = LO + 1; k <= HI; ++k) {
    const V uk = load(u + k * W);  // bead k − 1, before its drift
    const V fk = bond_force<hertz>(law, k, uk - load(u + (k + 1) * W));
    V force = previous - fk;
    if constexpr (grounded) force -= onsite_restoring_lanes<quartic>(law, k - 1, uk);
    const V v_old = load(v + (k - 1) * W);
    const V v_new = select(inside(k - 1, lo, hi), v_old + h * load(im + (k - 1) * W) * force, v_old);
    store(v + (k - 1) * W, v_new);
    store(u + k * W, uk + d * v_new);  // v = 0 outside a lane's window: u stays
    previous = fk;
  }
}

// The corrector of blocked_kernels.hpp (docs/physics.md, "Nonlinear dynamics"), then u += d v, on
// beads [LO, HI). A lane's accelerations outside its window are 0, as the one-chain kernel's
// never-written a[lo] and a[hi+1] are.
//
// Bead i's correction needs the accelerations of beads i − 1, i, i + 1. The loop computes bead
// i + 2's while it corrects bead i, so that a correction never waits for the square root of the
// same pass: the two halves of an iteration are independent and overlap (computing bead i + 1's
// there instead ran 1.8× slower). The arithmetic is the one-chain kernel's, only reordered.
template <bool hertz, bool grounded, bool quartic>
void correct_and_drift(const LaneLaw& law, double* __restrict u, double* __restrict v, const double* __restrict im,
                       const M& lo, const M& hi, std::size_t LO, std::size_t HI, double c, double d) {
  struct Bead {
    V u{}, im{}, a{};  // u before its drift; 1/m; the acceleration (0 outside the lane's window)
    M in{};            // the lanes whose window holds it
  };
  // Bond j + 1 joins beads j and j + 1 (padded rows j + 1 and j + 2). Bead j's acceleration needs
  // bonds j (f_left, carried) and j + 1, whose stiffness goes to `s_right`.
  V f_left, s_left;
  bond_force_stiffness<hertz>(law, LO, load(u + LO * W) - load(u + (LO + 1) * W), f_left, s_left);
  const auto acceleration = [&](std::size_t j, V& s_right) {
    Bead b;
    b.u = load(u + (j + 1) * W);
    b.im = load(im + j * W);
    b.in = inside(j, lo, hi);
    V f_right;
    bond_force_stiffness<hertz>(law, j + 1, b.u - load(u + (j + 2) * W), f_right, s_right);
    V force = f_left - f_right;
    if constexpr (grounded) force -= onsite_restoring_lanes<quartic>(law, j, b.u);
    b.a = select(b.in, b.im * force, V{});
    f_left = f_right;
    return b;
  };
  // At bead i: b0, b1 = beads i, i + 1 (all 0 past HI − 1); s0, s1, s2 = bonds i, i + 1, i + 2.
  V s0 = s_left, s1{}, s2{};
  Bead b0 = acceleration(LO, s1), b1{};
  if (LO + 1 < HI) b1 = acceleration(LO + 1, s2);
  V a_before{};  // bead i − 1's
  for (std::size_t i = LO; i < HI; ++i) {
    Bead b2{};
    V s3{};
    if (i + 2 < HI) b2 = acceleration(i + 2, s3);
    V g = s0 * (a_before - b0.a) - s1 * (b0.a - b1.a);
    if constexpr (grounded) g -= onsite_hessian_lanes<quartic>(law, i, b0.u) * b0.a;
    const V v_old = load(v + i * W);
    const V v_new = select(b0.in, v_old + c * b0.im * g, v_old);
    store(v + i * W, v_new);
    store(u + (i + 1) * W, b0.u + d * v_new);
    a_before = b0.a;
    b0 = b1;
    b1 = b2;
    s0 = s1;
    s1 = s2;
    s2 = s3;
  }
}

/// The lanes (of those in `active`) with a bead in their own [begin, end) whose kinetic energy
/// passes the window's threshold (window_rule.hpp), as SplittingPropagator's disturbed() judges it.
/// Rows first … last − 1 must cover every active lane's range.
inline M disturbed(const double* __restrict v, const double* __restrict im, const V& limit, const M& begin,
                   const M& end, const M& active, std::size_t first, std::size_t last) {
  M hit{};
  for (std::size_t i = first; i < last; ++i) {
    hit |= disturbs(load(v + i * W), limit, load(im + i * W)) & inside(i, begin, end);
  }
  return hit & active;
}

inline void drift_only(double* __restrict u, const double* __restrict v, std::size_t LO, std::size_t HI, double d) {
  for (std::size_t i = LO; i < HI; ++i) store(u + (i + 1) * W, load(u + (i + 1) * W) + d * load(v + i * W));
}

}  // namespace detail::lane_kernels
}  // namespace granular
