#include "granular/linear/detail/twisted_lanes.hpp"

#include "granular/parallel/detail/vector_lanes.hpp"

#include <algorithm>
#include <cmath>

namespace granular::detail {

namespace {

constexpr std::size_t L = twisted_lane_count;
constexpr double pivot_floor = 1e-290;  // a zero pivot becomes -pivot_floor (|e| ≤ 1 after scaling)
constexpr double node_ratio = 1e3;      // |L⁺| or |U⁻| above this: a near-zero pivot, a node of z
constexpr double negligible = 1e-60;    // |z| below this (z_r = 1) ends a recurrence

// The lanes are H native vectors of W doubles (vector_lanes.hpp).
using namespace lanes;
constexpr std::size_t H = L / W;
static_assert(L % W == 0);

// One z sweep away from the twist (z_r = 1 in every lane) for the G vectors from `first`. Up:
// i = max r − 1 … 0 with z_i = −L⁺_i z_{i+1}; down: i = min r … n − 2 with z_{i+1} = −U_i z_i.
// A lane joins at its own twist and leaves once |z| and the previous |z| are negligible (a left
// lane adds +0, which leaves a sum unchanged). Where a pivot is tiny the eigenvector has a node
// next to it and 0·∞ would lose the far lump: the three-term row of (T − σ) z = 0 carries z
// across instead, computed only at the rows `node` marks (some lane's |L⁺| or |U⁻| is large).
// All lanes sweep together (G = H vectors from `first`): per-vector or per-8-lane sweeps with
// their own ranges measured no faster, the shared loop overhead outweighing the tighter ranges.
constexpr std::size_t G = H;

template <bool Up>
void sweep(const double* d, const double* e, const double* m, std::size_t n, const double* factor,
           const unsigned char* node_rows, const V (&sigma)[H], const V (&twist)[H], std::size_t first, V (&z2)[H],
           V (&v2)[H], V (&v4)[H]) {
  V z[G], z1[G];
  M alive[G];
  std::size_t start = Up ? 0 : n;
  for (std::size_t g = 0; g < G; ++g) {
    const std::size_t h = first + g;
    z[g] = V{} + 1.0;
    z1[g] = V{};
    alive[g] = Up ? (twist[h] > 0.0) : (twist[h] < static_cast<double>(n - 1));
    for (std::size_t w = 0; w < W; ++w) {
      const auto r = static_cast<std::size_t>(twist[h][w]);
      start = Up ? std::max(start, r) : std::min(start, r);
    }
  }
  const std::size_t steps = Up ? start : n - 1 - start;
  for (std::size_t k = 0; k < steps; ++k) {
    const std::size_t i = Up ? start - 1 - k : start + k;
    if (k % 8 == 0 && !any(alive)) break;  // a few dead steps cost less than a check each step
    const double mi = Up ? m[i] : m[i + 1];
    const double di = Up ? d[i + 1] : d[i];
    const bool edge = Up ? i + 2 < n : i > 0;
    const double e_far = edge ? (Up ? e[i + 1] : e[i - 1]) : 0.0;
    for (std::size_t g = 0; g < G; ++g) {
      const std::size_t h = first + g;
      const M active =
          alive[g] & (Up ? (M)(static_cast<double>(i) < twist[h]) : (M)(static_cast<double>(i) >= twist[h]));
      const V f = load(factor + i * L + h * W);
      V next = -f * z[g];
      if (node_rows[i]) {
        const V three = -((di - sigma[h]) * z[g] + (edge ? e_far * z1[g] : V{} + 0.0)) / e[i];
        next = (active & (M)(vabs(f) > node_ratio)) ? three : next;
      }
      const V nz1 = active ? z[g] : z1[g], nz = active ? next : z[g];
      const M keep = (M)(vabs(nz) >= negligible) | (M)(vabs(nz1) >= negligible);
      alive[g] &= ~active | keep;
      z[g] = nz;
      z1[g] = nz1;
      const V zc = (active & keep) ? nz : V{};
      const V v = zc * mi, vv = v * v;
      z2[h] += zc * zc;
      v2[h] += vv;
      v4[h] += vv * vv;
    }
  }
}

// The z sweeps of one shift, scalar: L⁺ and U⁻ at lp[i·stride] and um[i·stride]; `s` holds the
// z_r = 1 term. twisted_one's, and twisted_lanes' where vectors are only 2 wide (no AVX): there
// masked vector sweeps cost more than the scalar ones, which stop at each lane's own end.
void scalar_sweeps(const double* d, const double* e, const double* m, std::size_t n, const double* lp, const double* um,
                   std::size_t stride, double sigma, TwistedSums& s) {
  const std::size_t r = s.twist;
  auto add = [&](double z, double mass) {
    const double v = z * mass, vv = v * v;
    s.z2 += z * z;
    s.v2 += vv;
    s.v4 += vv * vv;
  };
  double z = 1.0, z1 = 0;  // z1: the component one further from the twist
  for (std::size_t i = r; i-- > 0;) {
    const double li = lp[i * stride];
    const double next =
        std::fabs(li) > node_ratio ? -((d[i + 1] - sigma) * z + (i + 2 < n ? e[i + 1] * z1 : 0.0)) / e[i] : -li * z;
    z1 = z;
    z = next;
    if (!(std::fabs(z) >= negligible) && !(std::fabs(z1) >= negligible)) break;
    add(z, m[i]);
  }
  z = 1.0;
  z1 = 0;
  for (std::size_t i = r; i + 1 < n; ++i) {
    const double ui = um[i * stride];
    const double next =
        std::fabs(ui) > node_ratio ? -((d[i] - sigma) * z + (i > 0 ? e[i - 1] * z1 : 0.0)) / e[i] : -ui * z;
    z1 = z;
    z = next;
    if (!(std::fabs(z) >= negligible) && !(std::fabs(z1) >= negligible)) break;
    add(z, m[i + 1]);
  }
}

}  // namespace

void TwistedLaneWork::reserve(std::size_t n) {
  for (auto* v : {&lplus, &dplus, &uminus})
    if (v->size() < n * L) v->resize(n * L);
  for (auto* v : {&node_up, &node_down})
    if (v->size() < n) v->resize(n);
}

void twisted_lanes(const double* d, const double* e, const double* m, std::size_t n, const double* shift,
                   TwistedLaneWork& work, TwistedSums* out) {
  work.reserve(n);
  double* lp = work.lplus.data();
  double* dp = work.dplus.data();
  double* um = work.uminus.data();
  V sigma[H], piv[H], best[H], twist[H];
  for (std::size_t h = 0; h < H; ++h) sigma[h] = load(shift + h * W);

  // Both factorizations in one loop: each is a serial chain of divisions (~25 cycles a step),
  // so the two directions and the H vectors of each overlap (2H independent chains).
  // stationary L D Lᵀ = T − σ from the top: D⁺_{i+1} = d_{i+1} − σ − e_i L⁺_i, L⁺_i = e_i / D⁺_i;
  // progressive U D Uᵀ from the bottom: U_i = e_i / D⁻_{i+1}, D⁻_i = d_i − σ − e_i U_i.
  V down[H];
  for (std::size_t h = 0; h < H; ++h) {
    piv[h] = d[0] - sigma[h];
    down[h] = d[n - 1] - sigma[h];
  }
  unsigned char* node_up = work.node_up.data();
  unsigned char* node_down = work.node_down.data();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const std::size_t j = n - 2 - i;
    const double ei = e[i], dn = d[i + 1], ej = e[j], dj = d[j];
    M large_l[H], large_u[H];
    for (std::size_t h = 0; h < H; ++h) {
      const V p = vabs(piv[h]) < pivot_floor ? V{} - pivot_floor : piv[h];
      const V q = vabs(down[h]) < pivot_floor ? V{} - pivot_floor : down[h];
      const V li = ei / p;
      const V uj = ej / q;
      store(dp + i * L + h * W, p);
      store(lp + i * L + h * W, li);
      store(um + j * L + h * W, uj);
      piv[h] = (dn - sigma[h]) - ei * li;
      down[h] = (dj - sigma[h]) - ej * uj;
      large_l[h] = vabs(li) > node_ratio;
      large_u[h] = vabs(uj) > node_ratio;
    }
    node_up[i] = any(large_l);
    node_down[j] = any(large_u);
  }
  // the twist r minimizing |γ_r|, γ_{n-1} = D⁺_{n-1}, γ_i = D⁺_i − e_i U_i (ties: the largest i)
  for (std::size_t h = 0; h < H; ++h) {
    store(dp + (n - 1) * L + h * W, piv[h]);
    best[h] = vabs(piv[h]);
    twist[h] = V{} + static_cast<double>(n - 1);
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    const double ei = e[i];
    for (std::size_t h = 0; h < H; ++h) {
      const V g = vabs(load(dp + i * L + h * W) - ei * load(um + i * L + h * W));
      const M better = g < best[h];
      best[h] = better ? g : best[h];
      twist[h] = better ? V{} + static_cast<double>(i) : twist[h];
    }
  }

  // z_r = 1 in every lane: the sums start with that component
  V z2[H], v2[H], v4[H];
  for (std::size_t h = 0; h < H; ++h) {
    V mr;
    for (std::size_t w = 0; w < W; ++w) mr[w] = m[static_cast<std::size_t>(twist[h][w])];
    const V v = 1.0 * mr, vv = v * v;
    z2[h] = V{} + 1.0;
    v2[h] = vv;
    v4[h] = vv * vv;
  }
  if constexpr (W < 4) {
    for (std::size_t h = 0; h < H; ++h)
      for (std::size_t w = 0; w < W; ++w) {
        const std::size_t l = h * W + w;
        out[l] = {best[h][w], z2[h][w], v2[h][w], v4[h][w], static_cast<std::size_t>(twist[h][w])};
        scalar_sweeps(d, e, m, n, lp + l, um + l, L, shift[l], out[l]);
      }
    return;
  }
  for (std::size_t h = 0; h < H; h += G) {
    sweep<true>(d, e, m, n, lp, node_up, sigma, twist, h, z2, v2, v4);
    sweep<false>(d, e, m, n, um, node_down, sigma, twist, h, z2, v2, v4);
  }
  for (std::size_t h = 0; h < H; ++h)
    for (std::size_t w = 0; w < W; ++w)
      out[h * W + w] = {best[h][w], z2[h][w], v2[h][w], v4[h][w], static_cast<std::size_t>(twist[h][w])};
}

TwistedSums twisted_one(const double* d, const double* e, const double* m, std::size_t n, double sigma,
                        std::vector<double>& work) {
  if (work.size() < 3 * n) work.resize(3 * n);
  double* lp = work.data();
  double* dp = lp + n;
  double* um = dp + n;
  double piv = d[0] - sigma;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double p = std::fabs(piv) < pivot_floor ? -pivot_floor : piv;
    const double li = e[i] / p;
    dp[i] = p;
    lp[i] = li;
    piv = (d[i + 1] - sigma) - e[i] * li;
  }
  dp[n - 1] = piv;
  double best = std::fabs(piv);
  std::size_t r = n - 1;
  piv = d[n - 1] - sigma;
  for (std::size_t i = n - 1; i-- > 0;) {
    const double p = std::fabs(piv) < pivot_floor ? -pivot_floor : piv;
    const double ui = e[i] / p;
    um[i] = ui;
    piv = (d[i] - sigma) - e[i] * ui;
    const double g = std::fabs(dp[i] - e[i] * ui);
    if (g < best) {
      best = g;
      r = i;
    }
  }
  TwistedSums s{best, 1.0, 0, 0, r};
  const double v = 1.0 * m[r], vv = v * v;
  s.v2 = vv;
  s.v4 = vv * vv;
  scalar_sweeps(d, e, m, n, lp, um, 1, sigma, s);
  return s;
}

}  // namespace granular::detail
