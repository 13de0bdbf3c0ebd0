#include "granular/model/disorder.hpp"

#include <algorithm>
#include <cmath>

#include "granular/detail/enum_names.hpp"
#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {

constexpr auto disorder_names = detail::enum_names<Disorder>("disorder",
                                                             {{Disorder::homogeneous, "h"},
                                                              {Disorder::homogeneous, "homogeneous", true},
                                                              {Disorder::anderson, "A"},
                                                              {Disorder::anderson, "anderson", true},
                                                              {Disorder::rdm1, "RDM1"},
                                                              {Disorder::rdm2, "RDM2"}},
                                                             true, detail::Listing::one_of);

Disorder parse_disorder(std::string_view name) { return disorder_names.parse(name); }

std::string to_string(Disorder d) { return std::string(disorder_names.name_of(d)); }

void validate_probability(double q) {
  if (!(q >= 0 && q <= 1)) throw InvalidInput("q", " " + format_number(q) + ": must be in [0, 1]");
}

void validate_size_ratio(double xi) {
  if (!(xi > 0 && xi <= 1)) throw InvalidInput("xi", " " + format_number(xi) + ": must be in (0, 1]");
}

Configuration sample_configuration(Disorder disorder, double q, std::size_t n, RandomStream& stream) {
  validate_probability(q);
  Configuration types(n, 1);
  switch (disorder) {
    case Disorder::homogeneous: break;
    case Disorder::anderson:
      for (auto& t : types) t = stream.uniform() < q ? 1 : 2;
      break;
    case Disorder::rdm1:
    case Disorder::rdm2:
      for (std::size_t i = 0; i < n; i += 2) {
        const bool first = stream.uniform() < q;
        const std::uint8_t a = first ? 1 : 2;
        const std::uint8_t b = disorder == Disorder::rdm1 ? a : (first ? 2 : 1);
        types[i] = a;
        if (i + 1 < n) types[i + 1] = b;  // odd N: the last dimer loses its second bead
      }
      break;
  }
  return types;
}

Configuration realization_configuration(Disorder disorder, double q, std::size_t n, std::uint64_t seed,
                                        std::uint64_t realization) {
  RandomStream stream(seed, realization);
  return sample_configuration(disorder, q, n, stream);
}

std::vector<double> radii_of(const Configuration& types, double r1, double xi) {
  validate_size_ratio(xi);
  std::vector<double> radii(types.size());
  for (std::size_t i = 0; i < types.size(); ++i) radii[i] = types[i] == 1 ? r1 : xi * r1;
  return radii;
}

}  // namespace granular
