#include "granular/dynamics/force_law.hpp"

#include <string>

#include "granular/detail/enum_names.hpp"
#include "granular/error.hpp"
#include "granular/model/contact_law.hpp"

namespace granular {

constexpr auto force_law_names = detail::enum_names<ForceLawKind>(
    "force_law", {{ForceLawKind::hertz, "hertz"}, {ForceLawKind::fpu, "fpu"}, {ForceLawKind::linear, "linear"}}, true);

ForceLawKind parse_force_law(std::string_view name) { return force_law_names.parse(name); }

std::string to_string(ForceLawKind kind) { return std::string(force_law_names.name_of(kind)); }

OnsiteSprings::OnsiteSprings(const Chain& chain) : k_(chain.onsite), q_(chain.onsite_quartic) {
  if (!k_.empty() && k_.size() != chain.size())
    throw InvalidInput("onsite",
                       ": " + std::to_string(k_.size()) + " springs for " + std::to_string(chain.size()) + " beads");
  if (!q_.empty() && q_.size() != k_.size())
    throw InvalidInput("onsite_quartic", ": " + std::to_string(q_.size()) + " quartic parts for " +
                                             std::to_string(k_.size()) + " on-site springs (give k_n, 0 if none)");
}

namespace {

// Hertz and FPU describe contacts; a chain of linear springs (Chain::spring) has none.
const Chain& with_contacts(const Chain& chain, ForceLawKind kind) {
  if (!chain.spring.empty())
    throw InvalidInput("force_law", " " + to_string(kind) + ": the chain's bonds are linear springs (use linear)");
  return chain;
}

}  // namespace

HertzLaw::HertzLaw(const Chain& chain)
    : OnsiteSprings(with_contacts(chain, ForceLawKind::hertz)), contact_(chain.contact), overlap_(chain.overlap),
      rest_(chain.bonds(), 0.0), rest_potential_(chain.bonds()) {
  // The rest force through the kernel itself (rest_ = 0 here), so force(k, 0) == 0 exactly.
  for (std::size_t k = 0; k < bonds(); ++k) rest_[k] = view().force(k, 0.0);
  for (std::size_t k = 0; k < bonds(); ++k) {
    const double d = overlap_[k];
    rest_potential_[k] = 0.4 * contact_[k] * d * d * std::sqrt(d);
  }
}

PolynomialLaw::PolynomialLaw(const Chain& chain, int degree)
    : OnsiteSprings(chain), precompression_(chain.precompression) {
  const std::size_t n = chain.bonds();
  if (!chain.spring.empty()) {
    if (degree != 1) with_contacts(chain, ForceLawKind::fpu);
    c1_ = chain.spring;
    c2_.assign(n, 0.0);
    c3_.assign(n, 0.0);
    return;
  }
  if (!(chain.precompression > 0))
    throw InvalidInput("force_law", " " + std::string(degree == 1 ? "linear" : "fpu") +
                                        ": needs F0 > 0 (the sonic vacuum has no expansion about rest)");
  c1_.resize(n);
  c2_.assign(n, 0.0);
  c3_.assign(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const FpuCoefficients b = fpu_coefficients(chain.contact[k], chain.precompression);
    c1_[k] = b.b1;
    if (degree == 3) {
      c2_[k] = b.b2;
      c3_[k] = b.b3;
    }
  }
}

ForceLaw make_force_law(ForceLawKind kind, const Chain& chain) {
  switch (kind) {
    case ForceLawKind::hertz: return HertzLaw(chain);
    case ForceLawKind::fpu: return PolynomialLaw(chain, 3);
    case ForceLawKind::linear: return PolynomialLaw(chain, 1);
  }
  throw InvalidInput("unknown force law");
}

}  // namespace granular
