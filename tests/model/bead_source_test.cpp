// Bead sources: a streamed random realization is exactly the chain that
// realization_configuration + make_chain build, whatever the pieces it is read in.
#include <gtest/gtest.h>

#include <random>

#include "fixtures.hpp"
#include "granular/error.hpp"
#include "granular/linear/dynamical_matrix.hpp"
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
  const BidisperseBeads beads{fixtures::r1, 0.4, 2.5, steel};
  for (Disorder kind : {Disorder::homogeneous, Disorder::anderson, Disorder::rdm1, Disorder::rdm2})
    for (std::size_t n : {2u, 3u, 1000u, 4097u})
      for (std::uint64_t r : {0u, 5u}) {
        const Chain chain =
            make_chain(radii_of(realization_configuration(kind, 0.3, n, 17, r), beads.r1, beads.xi), beads.precompression);
        const auto source = random_beads(kind, 0.3, n, 17, r, beads);
        ASSERT_EQ(source->size(), n);
        const Beads got = read_in_pieces(*source, static_cast<unsigned>(n + r));
        EXPECT_EQ(got.mass, chain.mass) << to_string(kind) << " N=" << n << " r=" << r;
        EXPECT_EQ(got.stiffness, linear_stiffness(chain)) << to_string(kind) << " N=" << n << " r=" << r;
      }
}

TEST(BeadSource, OtherSeedsAndRealizationsGiveOtherChains) {
  std::vector<double> a(500), b(500), c(500), s(501);
  random_beads(Disorder::anderson, 0.5, 500, 1, 0)->read(0, 500, a.data(), s.data());
  random_beads(Disorder::anderson, 0.5, 500, 1, 1)->read(0, 500, b.data(), s.data());
  random_beads(Disorder::anderson, 0.5, 500, 2, 0)->read(0, 500, c.data(), s.data());
  EXPECT_NE(a, b);
  EXPECT_NE(a, c);
}

TEST(BeadSource, TypesAndChainsGiveTheirOwnBeads) {
  const Configuration types{1, 2, 2, 1, 2, 1, 1, 1, 2};
  const BidisperseBeads beads{fixtures::r1, 0.7, 10, steel};
  const Chain chain = make_chain(radii_of(types, beads.r1, beads.xi), beads.precompression);
  const Beads typed = read_in_pieces(*typed_beads(types, beads), 1);
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
  auto message = [](auto make) {
    try {
      make();
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_NE(message([] { random_beads(Disorder::anderson, 0.5, 100, 1, 0, {fixtures::r1, 0.5, 0, steel}); })
                .find("precompression"), std::string::npos);
  EXPECT_NE(message([] { random_beads(Disorder::anderson, 0.5, 1, 1, 0); }).find("N = 1"), std::string::npos);
  EXPECT_NE(message([] { random_beads(Disorder::anderson, 1.5, 10, 1, 0); }).find("q"), std::string::npos);
  EXPECT_NE(message([] { random_beads(Disorder::anderson, 0.5, 10, 1, 0, {fixtures::r1, 0, 10, steel}); }).find("xi"),
            std::string::npos);
  EXPECT_NE(message([] { random_beads(Disorder::anderson, 0.5, 10, 1, 0, {-1, 0.5, 10, steel}); }).find("r1"),
            std::string::npos);
  EXPECT_NE(message([] { typed_beads({1, 3}); }).find("bead 2"), std::string::npos);
  EXPECT_NE(message([] { chain_beads(fixtures::homogeneous(5, 0)); }).find("precompression"), std::string::npos);
  std::vector<double> m(5), s(6);
  EXPECT_THROW(random_beads(Disorder::anderson, 0.5, 10, 1, 0)->read(6, 5, m.data(), s.data()), InvalidInput);
}

}  // namespace
}  // namespace granular
