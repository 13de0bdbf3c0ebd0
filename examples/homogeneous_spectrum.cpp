// The spectrum of a homogeneous chain against its closed form.
//
// N identical steel beads (R = 4.76 mm, F0 = 10 N) between two fixed steel spheres of the same
// radius, so the two wall bonds equal the bulk bonds and the chain is exactly the textbook
// fixed-end lattice: f_k = (1/2π) sqrt(4B/m) sin(kπ / (2(N+1))), k = 1 … N (docs/physics.md).
// Checked: every frequency to 1e-10 relative. Exits 1 if any is off.
//
// The eigen-decomposition comes back from the library as Eigen vectors and is freed here, so
// this program also checks that it and libgranular agree on Eigen's memory layout.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <granular/linear/dynamical_matrix.hpp>
#include <granular/linear/lapack_eigensolver.hpp>
#include <granular/model/chain.hpp>

int main() {
  constexpr int N = 200;
  constexpr double radius = 4.76e-3;  // [m]
  granular::ChainSpec spec;
  spec.radii.assign(N, radius);
  spec.materials = {granular::steel};
  spec.left_wall.radius = spec.right_wall.radius = radius;  // wall bonds = bulk bonds
  spec.precompression = 10.0;                               // [N]
  const granular::Chain chain = granular::make_chain(spec);

  const granular::EigenDecomposition modes =
      granular::LapackEigensolver().solve(granular::dynamical_matrix(chain), /*want_vectors=*/true);

  const double stiffness = granular::linear_stiffness(chain.contact[1], chain.precompression);  // B [N/m]
  const double top_khz = std::sqrt(4 * stiffness / chain.mass[0]) / (2 * std::numbers::pi) * 1e-3;
  double worst = 0;
  for (int k = 1; k <= N; ++k) {
    const double exact = top_khz * std::sin(k * std::numbers::pi / (2.0 * (N + 1)));
    const double f = granular::frequency_khz(modes.values[k - 1]);
    worst = std::fmax(worst, std::fabs(f - exact) / exact);
    if (k <= 2 || k == N) std::printf("mode %3d: %.12f kHz (closed form %.12f)\n", k, f, exact);
  }
  std::printf("%d modes, %ld x %ld eigenvectors, largest relative error %.2e (limit 1e-10)\n", N,
              static_cast<long>(modes.vectors.rows()), static_cast<long>(modes.vectors.cols()), worst);
  return worst <= 1e-10 ? 0 : 1;
}
