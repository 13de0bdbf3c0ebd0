#include "granular/klein_gordon/klein_gordon.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "granular/error.hpp"
#include "granular/model/random_stream.hpp"
#include "granular/number_format.hpp"

namespace granular {

void validate(const KleinGordonParameters& p) {
  if (p.N < 2) throw InvalidInput("N", " " + std::to_string(p.N) + ": a chain needs at least 2 sites");
  if (p.N > 100000000)  // the granular chains' limit (named_chains.cpp)
    throw InvalidInput("N", " " + std::to_string(p.N) + ": more than 1e8 sites");
  if (!(p.W > 0) || !std::isfinite(p.W))
    throw InvalidInput("W", " " + format_number(p.W) + ": the disorder strength must be finite and > 0");
}

std::vector<double> klein_gordon_disorder(const KleinGordonParameters& p) {
  validate(p);
  RandomStream stream(p.seed, p.realization);
  std::vector<double> epsilon(p.N);
  for (double& e : epsilon) e = 0.5 + stream.uniform();
  return epsilon;
}

Chain klein_gordon(const KleinGordonParameters& p) {
  Chain c;
  c.onsite = klein_gordon_disorder(p);  // validates p
  const std::size_t n = p.N;
  c.radius.assign(n, std::numeric_limits<double>::infinity());
  c.mass.assign(n, 1.0);
  c.inverse_mass.assign(n, 1.0);
  c.contact.assign(n + 1, 0.0);
  c.overlap.assign(n + 1, 0.0);
  c.precompression = 0;
  c.onsite_quartic.assign(n, 1.0);
  c.spring.assign(n + 1, 1 / p.W);
  return c;
}

KleinGordonBand klein_gordon_band(double W) {
  validate(KleinGordonParameters{.N = 2, .W = W});
  // Gershgorin: ε̃ + 2/W ± 2/W, with ε̃ in [1/2, 3/2].
  return {0.5, 1.5 + 4 / W};
}

}  // namespace granular
