#include "granular/case/mode_kick.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/error.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/number_format.hpp"

namespace granular {

void validate(const ModeKick& kick, std::size_t beads) {
  const bool by_number = kick.mode != 0, by_frequency = kick.near_khz.has_value();
  if (by_number == by_frequency)
    throw InvalidInput("mode", ": give either a mode number or a frequency (`near_khz`), not both or neither");
  if (by_number && (kick.mode < 1 || static_cast<std::size_t>(kick.mode) > beads))
    throw InvalidInput("mode", " " + std::to_string(kick.mode) + ": outside 1.." + std::to_string(beads));
  if (by_frequency && !(std::isfinite(*kick.near_khz) && *kick.near_khz >= 0))
    throw InvalidInput("near_khz", " " + format_number(*kick.near_khz) + ": must be finite and >= 0 [kHz]");
  if (!std::isfinite(kick.energy) || kick.energy < 0)
    throw InvalidInput("energy", " " + format_number(kick.energy) + ": must be finite and >= 0 [J] (0: use amplitude)");
  if (kick.energy == 0 && !(std::isfinite(kick.amplitude) && kick.amplitude > 0))
    throw InvalidInput("amplitude", " " + format_number(kick.amplitude) + ": must be finite and > 0 [m]");
}

ModeKickResult mode_kick(const Chain& chain, ForceLawKind law_kind, const ModeKick& kick) {
  validate(kick, chain.size());
  const DynamicalMatrix d = dynamical_matrix(chain);
  const SpectrumConfig with_vector{.method = SpectrumMethod::bisect, .vectors = true};
  Spectrum found;
  std::size_t j = 0;
  if (kick.mode != 0) {
    // The frequency of mode K from the eigenvalues alone, then its vector among the modes nearest
    // that frequency (three, so that a near-degenerate neighbour cannot take its place).
    const Spectrum values = spectrum(d, all_modes(), {.method = SpectrumMethod::fast});
    const auto k = static_cast<std::size_t>(kick.mode);
    found =
        spectrum(d, nearest(values.freq_khz[k - 1], std::min<long>(3, static_cast<long>(chain.size()))), with_vector);
    j = static_cast<std::size_t>(std::find(found.mode.begin(), found.mode.end(), k) - found.mode.begin());
    if (j == found.size())
      throw NumericalError("mode " + std::to_string(k) + ": not among the modes nearest its own frequency");
  } else {
    found = spectrum(d, nearest(*kick.near_khz, 1), with_vector);
  }
  ModeKickResult r;
  r.mode = found.mode[j];
  r.freq_khz = found.freq_khz[j];
  r.omega2 = found.omega2[j];
  r.ipr = found.ipr[j];
  const auto w = found.vector(j);
  r.vector.assign(w.begin(), w.end());
  std::vector<double> shape(chain.size());
  for (std::size_t n = 0; n < shape.size(); ++n) shape[n] = w[n] * d.inverse_sqrt_mass[n];
  r.peak_site = static_cast<std::size_t>(
      std::max_element(shape.begin(), shape.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }) -
      shape.begin());
  const ForceLaw law = make_force_law(law_kind, chain);
  r.amplitude = kick.energy > 0 ? shaped_amplitude_for_energy(law, chain, shape, kick.energy) : kick.amplitude;
  r.initial = shaped_displacement(chain, shape, r.amplitude);
  r.energy = total_energy(law, chain, r.initial);
  return r;
}

nlohmann::json to_json(const ModeKickResult& kick) {
  return {{"mode", kick.mode},       {"freq_khz", kick.freq_khz},
          {"ipr", kick.ipr},         {"amplitude_m", kick.amplitude},
          {"energy_J", kick.energy}, {"peak_site", kick.peak_site + 1}};
}

double mode_energy_fraction(const DynamicalMatrix& d, std::span<const double> w, double omega2, const State& state) {
  const std::size_t n = d.size();
  if (w.size() != n || state.size() != n)
    throw InvalidInput("state", ": sizes of the matrix, the mode and the state differ");
  std::vector<double> x(n), p(n), dx(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = state.u[i] / d.inverse_sqrt_mass[i];  // M^{1/2} u
    p[i] = state.v[i] / d.inverse_sqrt_mass[i];  // M^{1/2} v
  }
  d.multiply(x.data(), dx.data());
  double q = 0, qdot = 0, kinetic = 0, potential = 0;
  for (std::size_t i = 0; i < n; ++i) {
    q += w[i] * x[i];
    qdot += w[i] * p[i];
    kinetic += p[i] * p[i];
    potential += x[i] * dx[i];
  }
  const double total = kinetic + potential;
  return total > 0 ? (qdot * qdot + omega2 * q * q) / total : 0.0;
}

}  // namespace granular

namespace granular {

double mode_amplitude_ipr(const State& state, double omega2) {
  if (!(omega2 > 0)) throw InvalidInput("omega2", " " + format_number(omega2) + ": must be > 0 [1/s^2]");
  double s2 = 0, s4 = 0;
  for (std::size_t n = 0; n < state.size(); ++n) {
    const double a2 = state.u[n] * state.u[n] + state.v[n] * state.v[n] / omega2;
    s2 += a2;
    s4 += a2 * a2;
  }
  return s2 > 0 ? s4 / (s2 * s2) : 0.0;
}

}  // namespace granular
