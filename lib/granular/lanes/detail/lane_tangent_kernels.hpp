#pragma once
// The tangent map's kernels (tangent_map.cpp) for W chains side by side, one per vector lane
// (lane_kernels.hpp): each lane's orbit and its one deviation vector w = (δu, δv) by the
// expressions of the one-chain kernels, so every lane is, bit for bit, its chain's
// TangentPropagator (tests/lanes/lane_tangent_propagator_test.cpp). The tangent map runs on the
// whole chain (no active window), so no lane is masked. Arrays are interleaved as in
// lane_kernels.hpp; u and δu are padded with the walls (row i + 1 is bead i).
#include <cstddef>

#include "granular/lanes/detail/lane_kernels.hpp"

namespace granular::detail::lane_kernels {

/// Bond k's curvature f_k'' at extension x, from its stiffness (force_law.hpp).
template <bool hertz>
inline V bond_curvature(const LaneLaw& law, std::size_t k, const V& x, const V& stiff) {
  const std::size_t at = k * W;
  if constexpr (hertz) return hertz_curvature_of<V>(load(law.p2 + at), x, stiff);
  else return polynomial_curvature_of<V>(load(law.p2 + at), load(law.p3 + at), x);
}

// v += h F/m and δv += h δF/m (δF_k = K_k δx_k; on-site springs add −(k + 3 q u²) δu), then
// u += d v and δu += d δv, on every bead: tangent_map.cpp's kick_and_drift, bond and bead fused.
template <bool hertz, bool grounded, bool quartic>
void tangent_kick_and_drift(const LaneLaw& law, double* __restrict u, double* __restrict du, double* __restrict v,
                            double* __restrict dv, const double* __restrict im, std::size_t n, double h, double d) {
  V f_left, s_left;
  bond_force_stiffness<hertz>(law, 0, load(u) - load(u + W), f_left, s_left);
  V kx_left = s_left * (load(du) - load(du + W));
  for (std::size_t k = 1; k <= n; ++k) {
    const V uk = load(u + k * W), duk = load(du + k * W);  // bead k − 1, before its drift
    V fk, sk;
    bond_force_stiffness<hertz>(law, k, uk - load(u + (k + 1) * W), fk, sk);
    const V kxk = sk * (duk - load(du + (k + 1) * W));
    V force = f_left - fk, dforce = kx_left - kxk;
    if constexpr (grounded) {
      force -= onsite_restoring_lanes<quartic>(law, k - 1, uk);
      dforce -= onsite_hessian_lanes<quartic>(law, k - 1, uk) * duk;
    }
    const V imk = load(im + (k - 1) * W);
    const V v_new = load(v + (k - 1) * W) + h * imk * force;
    const V dv_new = load(dv + (k - 1) * W) + h * imk * dforce;
    store(v + (k - 1) * W, v_new);
    store(u + k * W, uk + d * v_new);
    store(dv + (k - 1) * W, dv_new);
    store(du + k * W, duk + d * dv_new);
    f_left = fk;
    kx_left = kxk;
  }
}

// The corrector v_i += c im_i G_i and its derivative δv_i += c im_i δG_i, then the drifts, on
// every bead: tangent_map.cpp's correct_and_drift, with lane_kernels.hpp's look-ahead (bead
// i + 2's accelerations computed while bead i is corrected).
template <bool hertz, bool grounded, bool quartic>
void tangent_correct_and_drift(const LaneLaw& law, double* __restrict u, double* __restrict du, double* __restrict v,
                               double* __restrict dv, const double* __restrict im, std::size_t n, double c, double d) {
  struct Bead {
    V u{}, du{}, im{}, a{}, da{};  // before the drift; 1/m; acceleration and its derivative
    V hessian{}, curvature{};      // on-site: k + 3 q u² and (quartic) 6 q u
  };
  struct Bond {
    V stiff{}, cx{};  // K_k and f_k'' δx_k
  };
  // Bond j + 1 joins beads j and j + 1 (padded rows j + 1 and j + 2); bead j's accelerations need
  // bonds j (carried: f_left, kx_left) and j + 1 (returned in `right`).
  V f_left, kx_left;
  Bond left;
  {
    const V x = load(u) - load(u + W), dx = load(du) - load(du + W);
    bond_force_stiffness<hertz>(law, 0, x, f_left, left.stiff);
    kx_left = left.stiff * dx;
    left.cx = bond_curvature<hertz>(law, 0, x, left.stiff) * dx;
  }
  const auto acceleration = [&](std::size_t j, Bond& right) {
    Bead b;
    b.u = load(u + (j + 1) * W);
    b.du = load(du + (j + 1) * W);
    b.im = load(im + j * W);
    const V x = b.u - load(u + (j + 2) * W), dx = b.du - load(du + (j + 2) * W);
    V f_right;
    bond_force_stiffness<hertz>(law, j + 1, x, f_right, right.stiff);
    const V kx_right = right.stiff * dx;
    right.cx = bond_curvature<hertz>(law, j + 1, x, right.stiff) * dx;
    V force = f_left - f_right, dforce = kx_left - kx_right;
    if constexpr (grounded) {
      force -= onsite_restoring_lanes<quartic>(law, j, b.u);
      b.hessian = onsite_hessian_lanes<quartic>(law, j, b.u);
      dforce -= b.hessian * b.du;
      if constexpr (quartic) b.curvature = onsite_curvature_of<V>(load(law.onsite_quartic + j * W), b.u);
    }
    b.a = b.im * force;
    b.da = b.im * dforce;
    f_left = f_right;
    kx_left = kx_right;
    return b;
  };
  // At bead i: b0, b1 = beads i, i + 1 (0 past the last); k0, k1, k2 = bonds i, i + 1, i + 2.
  Bond k0 = left, k1{}, k2{};
  Bead b0 = acceleration(0, k1), b1{};
  if (n > 1) b1 = acceleration(1, k2);
  V a_before{}, da_before{};  // bead i − 1's (0 at the wall)
  for (std::size_t i = 0; i < n; ++i) {
    Bead b2{};
    Bond k3{};
    if (i + 2 < n) b2 = acceleration(i + 2, k3);
    V g = k0.stiff * (a_before - b0.a) - k1.stiff * (b0.a - b1.a);
    V dg =
        k0.cx * (a_before - b0.a) + k0.stiff * (da_before - b0.da) - k1.cx * (b0.a - b1.a) - k1.stiff * (b0.da - b1.da);
    if constexpr (grounded) {
      g -= b0.hessian * b0.a;
      dg -= b0.hessian * b0.da;
      if constexpr (quartic) dg -= b0.curvature * b0.du * b0.a;
    }
    const V v_new = load(v + i * W) + c * b0.im * g;
    const V dv_new = load(dv + i * W) + c * b0.im * dg;
    store(v + i * W, v_new);
    store(dv + i * W, dv_new);
    store(u + (i + 1) * W, b0.u + d * v_new);
    store(du + (i + 1) * W, b0.du + d * dv_new);
    a_before = b0.a;
    da_before = b0.da;
    b0 = b1;
    b1 = b2;
    k0 = k1;
    k1 = k2;
    k2 = k3;
  }
}

/// u += d v and δu += d δv on every bead.
inline void tangent_drift(double* __restrict u, double* __restrict du, const double* __restrict v,
                          const double* __restrict dv, std::size_t n, double d) {
  for (std::size_t i = 0; i < n; ++i) {
    store(u + (i + 1) * W, load(u + (i + 1) * W) + d * load(v + i * W));
    store(du + (i + 1) * W, load(du + (i + 1) * W) + d * load(dv + i * W));
  }
}

/// ‖w‖² = Σ δu_i² + (t δv_i)² of every lane, summed as TangentPropagator's norm sums it (four
/// partial sums by i mod 4, then (p0 + p1) + (p2 + p3)).
inline V squared_norms(const double* __restrict du, const double* __restrict dv, std::size_t n, double t) {
  V part[4] = {};
  const double tt = t * t;
  for (std::size_t i = 0; i < n; ++i) {
    const V x = load(du + (i + 1) * W), y = load(dv + i * W);
    part[i % 4] += x * x + tt * y * y;
  }
  return (part[0] + part[1]) + (part[2] + part[3]);
}

}  // namespace granular::detail::lane_kernels
