// A hexagonal granular crystal in the plane: its static state, every mode, and the Dirac point.
//
// A 12 × 8 torus of steel beads (R = 4.76 mm) under a compressive strain of 1e-3: the static state
// is the lattice itself, every contact pushing with f = A (2Rε)^{3/2}. At the zone corner
// K = (4π/3a, 0) the two acoustic branches meet at ω² = (9/2m)(k_n − f/d), four times over (K and
// −K, docs/crystals.md, "Bloch waves"). Checked: that level appears four times in the dense
// spectrum, to 1e-10 of the band top. Then the same crystal with walls and mass disorder: its modes'
// mean IPR low and high in the band. Exits 1 if the check fails.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <granular/granular.hpp>

int main() {
  granular::PackingSpec spec;
  spec.lattice = granular::Lattice::hexagonal;
  spec.boundary = granular::Boundary::periodic;
  spec.Lx = 12, spec.Ly = 8, spec.strain = 1e-3;
  const granular::Packing torus = granular::make_packing(spec);
  const granular::StaticState state = granular::static_state(torus);
  const granular::CrystalSpectrum modes = granular::crystal_spectrum(granular::crystal_matrix(torus, state));

  const double f = state.force[0], d = state.distance[0], kn = state.stiffness[0], m = torus.mass[0];
  const double dirac = 9 / (2 * m) * (kn - f / d);  // ω² at ±K [1/s²]
  int level = 0;
  for (double w2 : modes.omega2) level += std::fabs(w2 - dirac) < 1e-10 * modes.omega2.back();
  std::printf("%zu beads, contact force %.6f N, %zu modes up to %.3f kHz\n", torus.size(), f, modes.size(),
              modes.freq_hz.back() * 1e-3);
  std::printf("Dirac point: %.9f kHz, found %d times (expected 4)\n", std::sqrt(dirac) / (2 * std::numbers::pi) * 1e-3,
              level);

  spec.boundary = granular::Boundary::walls, spec.precompression = 10;  // F0 per boundary bead [N]
  const granular::Packing walls = granular::make_packing(
      granular::disordered(spec, {.kind = granular::PackingDisorder::Kind::mass, .width = 0.8, .seed = 3}));
  const granular::CrystalSpectrum disordered =
      granular::crystal_spectrum(granular::crystal_matrix(walls, granular::static_state(walls)));
  const std::size_t n = disordered.size();
  double low = 0, high = 0;
  for (std::size_t k = 0; k < n / 10; ++k) low += disordered.ipr[k], high += disordered.ipr[n - 1 - k];
  std::printf("with walls and mass disorder 0.8: mean IPR x N %.2f (lowest tenth), %.2f (highest tenth)\n",
              low / static_cast<double>(n / 10) * static_cast<double>(walls.size()),
              high / static_cast<double>(n / 10) * static_cast<double>(walls.size()));
  return level == 4 ? 0 : 1;
}
