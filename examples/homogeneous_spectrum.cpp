// The spectrum of a homogeneous chain against its closed form.
//
// N identical steel beads (R = 4.76 mm, F0 = 10 N) between two fixed steel spheres of the same
// radius, so the two wall bonds equal the bulk bonds and the chain is exactly the textbook
// fixed-end lattice: f_k = (1/2π) sqrt(4B/m) sin(kπ / (2(N+1))), k = 1 … N (docs/physics.md §3).
// Checked: every frequency to 1e-10 relative, and the mode IPR of a standing wave (N+1 odd),
// Σ sin⁴ / (Σ sin²)² = 3 / (2(N+1)) for every mode, to 1e-10. Exits 1 if any is off.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <granular/granular.hpp>

int main() {
  constexpr int N = 200;
  granular::ChainSpec spec;
  spec.radii.assign(N, granular::paper_r1);
  spec.materials = {granular::steel};
  spec.left_wall.radius = spec.right_wall.radius = granular::paper_r1;  // wall bonds = bulk bonds
  spec.precompression = 10.0;                                           // [N]
  const granular::Chain chain = granular::make_chain(spec);

  const granular::Spectrum modes =
      granular::spectrum(granular::dynamical_matrix(chain), granular::all_modes(), {.vectors = true});

  const double stiffness = granular::linear_stiffness(chain.contact[1], chain.precompression);  // B [N/m]
  const double top_khz = std::sqrt(4 * stiffness / chain.mass[0]) / (2 * std::numbers::pi) * 1e-3;
  const double standing_wave_ipr = 3.0 / (2.0 * (N + 1));
  double worst_f = 0, worst_ipr = 0;
  for (int k = 1; k <= N; ++k) {
    const double exact = top_khz * std::sin(k * std::numbers::pi / (2.0 * (N + 1)));
    const double f = modes.freq_khz[k - 1];
    worst_f = std::fmax(worst_f, std::fabs(f - exact) / exact);
    worst_ipr = std::fmax(worst_ipr, std::fabs(modes.ipr[k - 1] - standing_wave_ipr) / standing_wave_ipr);
    if (k <= 2 || k == N)
      std::printf("mode %3d: %.12f kHz (closed form %.12f), IPR %.6f\n", k, f, exact, modes.ipr[k - 1]);
  }
  std::printf(
      "%zu modes by %s, %zu eigenvector entries; largest relative error: frequency %.2e, IPR %.2e "
      "(limit 1e-10)\n",
      modes.size(), modes.info.method.c_str(), modes.vectors.size(), worst_f, worst_ipr);
  return worst_f <= 1e-10 && worst_ipr <= 1e-10 && modes.vectors.size() == std::size_t{N} * N ? 0 : 1;
}
