// One SABA2C run with observers: a displacement kick at the centre of a homogeneous chain
// (F0 = 10 N, 1401 beads, 10 ms: the wave does not reach the walls), measured by the energy-spread
// observer (m̃2 about the kicked bead and about the energy centroid, P⁻¹) and by the forces at
// three beads. Checked: linear waves spread ballistically, so m̃2 ∝ t² (γ = 2 ± 0.05 on 4–10 ms)
// and P⁻¹ ∝ 1/t (η = 1 ± 0.05); m̃2 about the energy centroid never exceeds m̃2 about the kicked
// bead (the centroid minimizes the second moment: their difference is (n̄ − n0)² ≥ 0); the force
// pulse reaches bead 801 (100 beads out) before bead 901, and both before T. Exits 1 if any fails.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <granular/granular.hpp>

int main() {
  const granular::Chain chain = granular::homogeneous({.N = 1401, .F0 = 10});
  const std::size_t centre = 700;
  granular::EnergySpreadObserver spread({.samples = 50, .dense = {4e-3, 1e-2, 1e-5}, .site = centre});
  granular::ForceObserver forces({.sites = {800, 900}, .samples = 2001});
  const granular::RunInfo info = granular::spread(chain, granular::displacement_kick(chain, centre, 1e-7),
                                                  {.duration = 1e-2, .time_step = 1e-6}, spread, forces);

  std::vector<double> inverse_ipr;
  for (double p : spread.ipr) inverse_ipr.push_back(1 / p);
  const double gamma = granular::windowed_exponent(spread.t, spread.m2, 4e-3, 1e-2).value;
  const double eta = granular::windowed_exponent(spread.t, inverse_ipr, 4e-3, 1e-2).value;
  double drift = 0;  // the largest |n̄ − n0| [beads]; the Hertz kick pushes right harder than it pulls left
  bool centroid_minimal = true;
  for (std::size_t i = 0; i < spread.t.size(); ++i) {
    centroid_minimal = centroid_minimal && spread.m2_centroid[i] <= spread.m2[i];
    drift = std::max(drift, std::sqrt(std::max(0.0, spread.m2[i] - spread.m2_centroid[i])));
  }
  const auto arrival = [&](std::size_t j) {  // first time the force departs from F0 by 1 mN
    for (std::size_t k = 0; k < forces.t.size(); ++k)
      if (std::abs(forces.forces[j][k] - 10.0) > 1e-3) return forces.t[k];
    return 1.0;
  };
  std::printf(
      "%llu steps: gamma = %.4f, eta = %.4f, centroid up to %.2f beads from the kicked bead, "
      "max energy error %.1e\n",
      static_cast<unsigned long long>(info.steps), gamma, eta, drift, spread.max_energy_error);
  std::printf("force pulse at bead 801 after %.3f ms, at bead 901 after %.3f ms\n", arrival(0) * 1e3, arrival(1) * 1e3);
  const bool ok = std::abs(gamma - 2) < 0.05 && std::abs(eta - 1) < 0.05 && centroid_minimal &&
                  arrival(0) < arrival(1) && arrival(1) < 1.0 && !spread.reached_walls();
  return ok ? 0 : 1;
}
