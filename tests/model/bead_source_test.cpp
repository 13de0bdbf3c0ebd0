// Bead sources: a streamed random realization is exactly the chain that
// realization_configuration + make_chain build, whatever the pieces it is read in.
#include <gtest/gtest.h>

#include <random>

#include "fixtures.hpp"
#include "granular/error.hpp"
#include "granular/model/bead_source.hpp"
#include "granular/model/random_stream.hpp"

namespace granular {
namespace {

struct Beads {
  std::vector<double> mass, stiffness;
};

/// The whole chain read in pieces of random sizes (1 … 700 beads), in random order.
Beads read_in_pieces(const BeadSource& source, unsigned shuffle_seed) {
  const std::size_t n = source.size();
  std::mt19937 rng(shuffle_seed);
  std::vector<std::pair<std::size_t, std::size_t>> pieces;
  for (std::size_t first = 0; first < n;) {
    const std::size_t count = std::min<std::size_t>(n - first, 1 + rng() % 700);
    pieces.emplace_back(first, count);
    first += count;
  }
  std::shuffle(pieces.begin(), pieces.end(), rng);
  Beads b{std::vector<double>(n), std::vector<double>(n + 1)};
  std::vector<double> m, s;
  for (auto [first, count] : pieces) {
    m.assign(count, -1);
    s.assign(count + 1, -1);
    source.read(first, count, m.data(), s.data());
    std::copy(m.begin(), m.end(), b.mass.begin() + static_cast<long>(first));
    for (std::size_t i = 0; i <= count; ++i) {
      if (b.stiffness[first + i] != 0) {
        EXPECT_EQ(b.stiffness[first + i], s[i]) << "bond " << first + i << " read twice differently";
      }
      b.stiffness[first + i] = s[i];
    }
  }
  return b;
}

TEST(RandomStream, BlocksAreTheSequentialDraws) {
  RandomStream sequential(3, 11);
  const RandomStream direct(3, 11);
  for (std::uint64_t b = 0; b < 50; ++b) {
    const auto block = direct.uniform_block(b);
    for (double u : block) EXPECT_EQ(u, sequential.uniform());
  }
}

TEST(BeadSource, StreamedRealizationIsExactlyTheBuiltChain) {
  for (Disorder kind : {Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2})
    for (std::size_t n : {2u, 3u, 1000u, 4097u})
      for (std::uint64_t r : {0u, 5u}) {
        const ChainParameters p{.N = n, .q = 0.3, .xi = 0.4, .seed = 17, .realization = r, .F0 = 2.5};
        // The chain as the rest of the toolkit builds it: types from realization_configuration.
        const Chain chain = make_chain(radii_of(realization_configuration(kind, p.q, n, p.seed, r), p.R1, p.xi), p.F0);
        const auto source = random_beads(kind, p);
        ASSERT_EQ(source->size(), n);
        const Beads got = read_in_pieces(*source, static_cast<unsigned>(n + r));
        EXPECT_EQ(got.mass, chain.mass) << to_string(kind) << " N=" << n << " r=" << r;
        EXPECT_EQ(got.stiffness, linear_stiffness(chain)) << to_string(kind) << " N=" << n << " r=" << r;
        EXPECT_EQ(got.mass, random_chain(kind, p).mass);
      }
}

TEST(BeadSource, OtherSeedsAndRealizationsGiveOtherChains) {
  std::vector<double> a(500), b(500), c(500), s(501);
  random_beads(Disorder::anderson, {.N = 500, .seed = 1, .realization = 0})->read(0, 500, a.data(), s.data());
  random_beads(Disorder::anderson, {.N = 500, .seed = 1, .realization = 1})->read(0, 500, b.data(), s.data());
  random_beads(Disorder::anderson, {.N = 500, .seed = 2, .realization = 0})->read(0, 500, c.data(), s.data());
  EXPECT_NE(a, b);
  EXPECT_NE(a, c);
}

TEST(BeadSource, StreamsAreNotLimitedToStoredChainSizes) {
  // 10⁹ beads: nothing is stored, and the last piece is as cheap as the first.
  const ChainParameters p{.N = 1000000000, .q = 0.5};
  const auto source = random_beads(Disorder::rdm2, p);
  std::vector<double> m(4), b(5);
  source->read(999999996, 4, m.data(), b.data());
  EXPECT_NE(m[2], m[3]);  // an RDM2 dimer holds one bead of each type
  const double m1 = from_types({1, 1}, p).mass[0];
  const Configuration last{std::uint8_t(m[2] == m1 ? 1 : 2), std::uint8_t(m[3] == m1 ? 1 : 2)};
  const auto tail = linear_stiffness(from_types(last, p));  // wall, bond, wall
  EXPECT_EQ(b[3], tail[1]);
  EXPECT_EQ(b[4], tail[2]);  // the right wall, a billion beads away
}

TEST(BeadSource, TypesAndChainsGiveTheirOwnBeads) {
  const Configuration types{1, 2, 2, 1, 2, 1, 1, 1, 2};
  const ChainParameters p{.xi = 0.7, .F0 = 10};
  const Chain chain = from_types(types, p);
  const Beads typed = read_in_pieces(*typed_beads(types, p), 1);
  EXPECT_EQ(typed.mass, chain.mass);
  EXPECT_EQ(typed.stiffness, linear_stiffness(chain));

  ChainSpec spec;  // polydisperse, odd walls: only the Chain source can carry it
  spec.radii = {3e-3, 4e-3, 5e-3, 2e-3, 4.5e-3};
  spec.materials = {steel};
  spec.left_wall.radius = 1e-3;
  spec.precompression = 3;
  const Chain odd = make_chain(spec);
  const Beads copied = read_in_pieces(*chain_beads(odd), 2);
  EXPECT_EQ(copied.mass, odd.mass);
  EXPECT_EQ(copied.stiffness, linear_stiffness(odd));
}

TEST(BeadSource, BadParametersAreNamed) {
  auto parameter = [](auto make) {
    try {
      make();
    } catch (const InvalidInput& e) {
      return e.parameter();
    }
    return std::string("no exception");
  };
  EXPECT_EQ(parameter([] { random_beads(Disorder::anderson, {.N = 100, .F0 = 0}); }), "F0");
  EXPECT_EQ(parameter([] { random_beads(Disorder::anderson, {.N = 1}); }), "N");
  EXPECT_EQ(parameter([] { random_beads(Disorder::anderson, {.N = 10, .q = 1.5}); }), "q");
  EXPECT_EQ(parameter([] { random_beads(Disorder::anderson, {.N = 10, .xi = 0}); }), "xi");
  EXPECT_EQ(parameter([] { random_beads(Disorder::anderson, {.N = 10, .R1 = -1}); }), "R1");
  EXPECT_EQ(parameter([] { typed_beads({1, 3}); }), "types");
  EXPECT_EQ(parameter([] { chain_beads(fixtures::homogeneous(5, 0)); }), "F0");
  std::vector<double> m(5), s(6);
  EXPECT_THROW(random_beads(Disorder::anderson, {.N = 10})->read(6, 5, m.data(), s.data()), InvalidInput);
}

}  // namespace
}  // namespace granular
