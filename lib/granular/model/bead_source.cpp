#include "granular/model/bead_source.hpp"

#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "granular/error.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/model/random_stream.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

void require_linear_limit(double precompression) {
  if (!(precompression > 0) || !std::isfinite(precompression))
    throw InvalidInput("F0", " " + format_number(precompression) +
                                 ": must be finite and > 0 (the sonic vacuum has no linear limit)");
}

/// Masses and bond stiffnesses of the two bead types, index 1 and 2 (0 unused). Taken from
/// two-bead chains built by from_types, so they are the very numbers a whole chain built by
/// from_types (or random_chain) holds, bit for bit.
struct TypeTable {
  std::array<double, 3> mass{}, left_wall{}, right_wall{};
  std::array<std::array<double, 3>, 3> bond{};

  explicit TypeTable(const ChainParameters& p) {
    require_linear_limit(p.F0);
    validate(p.material, "material");
    for (std::uint8_t a = 1; a <= 2; ++a)
      for (std::uint8_t c = 1; c <= 2; ++c) {
        const Chain pair = from_types({a, c}, p);  // validates xi and R1
        mass[a] = pair.mass[0];
        left_wall[a] = linear_stiffness(pair.contact[0], p.F0);
        bond[a][c] = linear_stiffness(pair.contact[1], p.F0);
        right_wall[c] = linear_stiffness(pair.contact[2], p.F0);
      }
  }

  /// Fills a piece given `type_of(i)` ∈ {1, 2} for bead i of an n-bead chain.
  template <class TypeOf>
  void fill(std::size_t n, std::size_t first, std::size_t count, TypeOf&& type_of, double* m, double* b) const {
    if (first + count > n || first > n)
      throw InvalidInput("first", " " + std::to_string(first) + " + count " + std::to_string(count) +
                                      ": beyond N = " + std::to_string(n));
    int left = first == 0 ? 0 : type_of(first - 1);  // 0: the wall
    for (std::size_t i = 0; i < count; ++i) {
      const int here = type_of(first + i);
      m[i] = mass[here];
      b[i] = left == 0 ? left_wall[here] : bond[left][here];
      left = here;
    }
    const std::size_t k = first + count;  // the last bond of the piece
    if (k == n) b[count] = right_wall[left];
    else if (left == 0) b[count] = left_wall[type_of(k)];
    else b[count] = bond[left][type_of(k)];
  }
};

class RandomBeads final : public BeadSource {
 public:
  RandomBeads(Disorder disorder, const ChainParameters& p)
      : table_(p), disorder_(disorder), q_(p.q), n_(p.N), stream_(p.seed, p.realization) {
    ChainParameters stored = p;
    stored.N = 2;  // validate(p) caps N for stored chains; a stream has no such limit
    validate(stored);
    if (p.N < 2) throw InvalidInput("N", " " + std::to_string(p.N) + ": a chain needs at least 2 beads");
  }
  std::size_t size() const override { return n_; }
  void read(std::size_t first, std::size_t count, double* mass, double* stiffness) const override {
    // The same rule as sample_configuration: bead i of A from uniform i; dimer j = i/2 of RDM1/RDM2
    // from uniform j, its second bead the same type (RDM1) or the other one (RDM2).
    std::uint64_t cached = ~std::uint64_t{0};
    std::array<double, 4> block{};
    auto uniform = [&](std::uint64_t j) {
      if (j / 4 != cached) block = stream_.uniform_block(cached = j / 4);
      return block[j % 4];
    };
    auto type_of = [&](std::size_t i) -> int {
      switch (disorder_) {
        case Disorder::homogeneous: return 1;
        case Disorder::anderson: return uniform(i) < q_ ? 1 : 2;
        case Disorder::rdm1: return uniform(i / 2) < q_ ? 1 : 2;
        case Disorder::rdm2: return (uniform(i / 2) < q_) == (i % 2 == 0) ? 1 : 2;
      }
      return 1;
    };
    table_.fill(n_, first, count, type_of, mass, stiffness);
  }

 private:
  TypeTable table_;
  Disorder disorder_;
  double q_;
  std::size_t n_;
  RandomStream stream_;
};

class TypedBeads final : public BeadSource {
 public:
  TypedBeads(Configuration types, const ChainParameters& p) : table_(p), types_(std::move(types)) {
    if (types_.size() < 2)
      throw InvalidInput("N", " " + std::to_string(types_.size()) + ": a chain needs at least 2 beads");
    for (std::size_t i = 0; i < types_.size(); ++i)
      if (types_[i] != 1 && types_[i] != 2)
        throw InvalidInput("types", ": bead " + std::to_string(i + 1) + " has type " + std::to_string(types_[i]) +
                                        " (must be 1 or 2)");
  }
  std::size_t size() const override { return types_.size(); }
  void read(std::size_t first, std::size_t count, double* mass, double* stiffness) const override {
    table_.fill(
        types_.size(), first, count, [&](std::size_t i) -> int { return types_[i]; }, mass, stiffness);
  }

 private:
  TypeTable table_;
  Configuration types_;
};

class ChainBeads final : public BeadSource {
 public:
  explicit ChainBeads(const Chain& chain) : mass_(chain.mass), onsite_(chain.onsite) {
    if (chain.spring.empty()) require_linear_limit(chain.precompression);
    stiffness_ = linear_stiffness(chain);
  }
  std::size_t size() const override { return mass_.size(); }
  void read(std::size_t first, std::size_t count, double* mass, double* stiffness) const override {
    if (first > mass_.size() || count > mass_.size() - first)
      throw InvalidInput("first", " " + std::to_string(first) + " + count " + std::to_string(count) +
                                      ": beyond N = " + std::to_string(mass_.size()));
    for (std::size_t i = 0; i < count; ++i) mass[i] = mass_[first + i];
    for (std::size_t i = 0; i <= count; ++i) stiffness[i] = stiffness_[first + i];
  }
  bool grounded() const override { return !onsite_.empty(); }
  void read_onsite(std::size_t first, std::size_t count, double* onsite) const override {
    if (onsite_.empty()) return BeadSource::read_onsite(first, count, onsite);
    if (first > onsite_.size() || count > onsite_.size() - first)
      throw InvalidInput("first", " " + std::to_string(first) + " + count " + std::to_string(count) +
                                      ": beyond N = " + std::to_string(onsite_.size()));
    for (std::size_t i = 0; i < count; ++i) onsite[i] = onsite_[first + i];
  }

 private:
  std::vector<double> mass_, onsite_, stiffness_;
};

}  // namespace

std::unique_ptr<BeadSource> random_beads(Disorder disorder, const ChainParameters& p) {
  return std::make_unique<RandomBeads>(disorder, p);
}

std::unique_ptr<BeadSource> typed_beads(Configuration types, const ChainParameters& p) {
  return std::make_unique<TypedBeads>(std::move(types), p);
}

std::unique_ptr<BeadSource> chain_beads(const Chain& chain) { return std::make_unique<ChainBeads>(chain); }

}  // namespace granular
