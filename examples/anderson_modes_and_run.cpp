// The 20-line program of issue 11: an Anderson chain, every mode's frequency and IPR, then SABA2C
// for 1 ms after a velocity kick, watched by an observer.
// Checked: N modes, frequencies strictly ascending, every IPR in (0, 1], and the relative energy
// error of the run below 1e-6 at every sample. Exits 1 if any fails.
#include <cstdio>

#include <granular/granular.hpp>

int main() {
  const granular::Chain chain = granular::anderson({.N = 100, .q = 0.5, .xi = 0.5, .seed = 1});
  const granular::Spectrum modes = granular::spectrum(granular::dynamical_matrix(chain));  // every mode
  bool ok = modes.size() == chain.size();
  for (std::size_t j = 0; j < modes.size(); ++j) {
    if (j % 20 == 0) std::printf("mode %3zu: %9.4f kHz, IPR %.4f\n", modes.mode[j], modes.freq_khz[j], modes.ipr[j]);
    ok = ok && modes.ipr[j] > 0 && modes.ipr[j] <= 1 && (j == 0 || modes.freq_khz[j] > modes.freq_khz[j - 1]);
  }

  granular::EnergySpreadObserver spread;  // m̃2, P⁻¹ and the energy error at 100 log-spaced times
  granular::spread(chain, granular::velocity_kick(chain, 49, 8e-3), {.duration = 1e-3, .time_step = 1e-6}, spread);
  std::printf("t = %g s: m2 = %.2f beads^2, P^-1 = %.4f, max relative energy error %.2e (limit 1e-6)\n",
              spread.t.back(), spread.m2.back(), spread.ipr.back(), spread.max_energy_error);
  return ok && spread.max_energy_error < 1e-6 ? 0 : 1;
}
