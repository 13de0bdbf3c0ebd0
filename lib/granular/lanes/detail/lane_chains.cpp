#include "granular/lanes/detail/lane_chains.hpp"

#include <type_traits>
#include <variant>

#include "granular/dynamics/propagator.hpp"
#include "granular/error.hpp"

namespace granular::detail {

LaneChains interleave(std::span<const ForceLaw> laws, std::span<const Chain> chains, const SplittingScheme& scheme,
                      double time_step, std::span<const State> initials, std::size_t width) {
  const std::size_t W = width;
  LaneChains c;
  c.n = chains.empty() ? 0 : chains.front().size();
  c.lanes = chains.size();
  if (chains.empty() || chains.size() > W)
    throw InvalidInput("lanes", " " + std::to_string(chains.size()) + ": between 1 and " + std::to_string(W) +
                                    " chains side by side on this CPU");
  if (laws.size() != c.lanes || initials.size() != c.lanes)
    throw InvalidInput("lanes: " + std::to_string(c.lanes) + " chains, " + std::to_string(laws.size()) + " laws, " +
                       std::to_string(initials.size()) + " initial states");
  if (scheme.drift.size() != scheme.kick.size() + 1 || scheme.kick.empty())
    throw InvalidInput("scheme " + scheme.name + ": needs s kicks and s+1 drifts");
  const auto quartic = [](const ForceLaw& law) { return std::visit([](const auto& l) { return l.quartic(); }, law); };
  c.hertz = std::holds_alternative<HertzLaw>(laws[0]);
  c.grounded = granular::grounded(laws[0]);
  c.quartic = quartic(laws[0]);
  for (std::size_t l = 0; l < c.lanes; ++l) {
    if (chains[l].size() != c.n)
      throw InvalidInput("lanes: chain " + std::to_string(l) + " has " + std::to_string(chains[l].size()) +
                         " beads, chain 0 " + std::to_string(c.n) + "; side by side they must have one length");
    const bool same_kind = std::holds_alternative<HertzLaw>(laws[l]) == c.hertz &&
                           granular::grounded(laws[l]) == c.grounded && quartic(laws[l]) == c.quartic;
    if (!same_kind) throw InvalidInput("lanes: the laws of chains 0 and " + std::to_string(l) + " are of other kinds");
    validate_propagation(chains[l], time_step, initials[l]);
  }

  const std::size_t n = c.n;
  c.u.assign((n + 2) * W, 0.0);
  c.v.assign(n * W, 0.0);
  c.im.assign(n * W, 0.0);
  c.p1.assign((n + 1) * W, 0.0);
  c.p2.assign((n + 1) * W, 0.0);
  c.p3.assign((n + 1) * W, 0.0);
  if (c.grounded) c.k.assign(n * W, 0.0);
  if (c.quartic) c.q.assign(n * W, 0.0);
  for (std::size_t l = 0; l < W; ++l) {
    const std::size_t from = l < c.lanes ? l : 0;
    std::visit(
        [&](const auto& law) {
          const auto view = law.view();
          const double* p[3];
          if constexpr (std::is_same_v<std::decay_t<decltype(law)>, HertzLaw>)
            p[0] = view.contact, p[1] = view.overlap, p[2] = view.rest;
          else p[0] = view.c1, p[1] = view.c2, p[2] = view.c3;
          for (std::size_t k = 0; k <= n; ++k) {
            c.p1[k * W + l] = p[0][k];
            c.p2[k * W + l] = p[1][k];
            c.p3[k * W + l] = p[2][k];
          }
          for (std::size_t i = 0; i < n; ++i) {
            if (c.grounded) c.k[i * W + l] = view.onsite[i];
            if (c.quartic) c.q[i * W + l] = view.onsite_quartic[i];
          }
        },
        laws[from]);
    put_lane(c.im, l, chains[from].inverse_mass, 0, W);
    if (l >= c.lanes) continue;
    put_lane(c.u, l, initials[l].u, 1, W);
    put_lane(c.v, l, initials[l].v, 0, W);
  }
  return c;
}

void put_lane(std::vector<double>& to, std::size_t lane, std::span<const double> values, std::size_t pad,
              std::size_t width) {
  for (std::size_t i = 0; i < values.size(); ++i) to[(i + pad) * width + lane] = values[i];
}

void take_lane(const std::vector<double>& from, std::size_t lane, std::size_t pad, std::size_t width,
               std::vector<double>& to, std::size_t begin, std::size_t end) {
  for (std::size_t i = begin; i < end; ++i) to[i] = from[(i + pad) * width + lane];
}

void check_lane(const LaneChains& c, std::size_t lane) {
  if (lane >= c.lanes) throw InvalidInput("lane", " " + std::to_string(lane) + ": only " + std::to_string(c.lanes));
}

}  // namespace granular::detail
