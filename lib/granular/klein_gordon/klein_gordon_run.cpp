#include "granular/klein_gordon/klein_gordon_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <string>

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/error.hpp"
#include "granular/lanes/lane_propagator.hpp"
#include "granular/lanes/lane_tangent_propagator.hpp"
#include "granular/number_format.hpp"

namespace granular {

void validate(const KleinGordonRunConfig& c) {
  validate(c.chain);
  if (!(c.energy > 0) || !std::isfinite(c.energy))
    throw InvalidInput("energy", " " + format_number(c.energy) + ": must be finite and > 0");
  if (c.block > c.chain.N)
    throw InvalidInput("block", " " + std::to_string(c.block) + ": at most N = " + std::to_string(c.chain.N));
  if (!(c.time_step > 0) || !std::isfinite(c.time_step))
    throw InvalidInput("time_step", " " + format_number(c.time_step) + ": must be finite and > 0");
  if (c.sample_steps.empty()) throw InvalidInput("sample_steps", ": at least one sample");
  if (!std::is_sorted(c.sample_steps.begin(), c.sample_steps.end()))
    throw InvalidInput("sample_steps", ": must be sorted");
  const double values = static_cast<double>(c.sample_steps.size()) * static_cast<double>(c.chain.N);
  if (c.energy_map && values > klein_gordon_energy_map_limit)
    throw InvalidInput("energy_map", ": " + std::to_string(c.sample_steps.size()) + " samples x N = " +
                                         std::to_string(c.chain.N) + " sites = " + format_number(values) +
                                         " values, above 2e8 (1.6 GB): fewer `samples` or sites");
}

namespace {

/// Realization r's chain and its start, as run_klein_gordon integrates them.
struct KleinGordonStart {
  Chain chain;
  State start;
};
KleinGordonStart klein_gordon_start(const KleinGordonRunConfig& config, std::uint64_t realization) {
  KleinGordonParameters p = config.chain;
  p.realization = realization;
  Chain chain = klein_gordon(p);
  const std::size_t n = chain.size(), centre = centre_site(n);
  State start = config.block == 0 ? site_energy_kick(chain, centre, config.energy)
                                  : block_energy_kick(chain, centre - std::min(centre, (config.block - 1) / 2),
                                                      config.block, config.energy, p.seed, realization);
  return {std::move(chain), std::move(start)};
}

/// What a run keeps of the state `s` at time t (mle: Λ(t), with the tangent map).
void sample(const KleinGordonRunConfig& config, const ForceLaw& law, const Chain& chain, double h0, const State& s,
            double t, const double* mle, KleinGordonRun& out) {
  const std::vector<double> energy = site_energies(law, chain, s);
  const EnergySpread spread = energy_spread(energy, centre_site(chain.size()));
  out.time.push_back(t);
  out.m2.push_back(spread.m2_centroid);
  out.participation.push_back(spread.ipr > 0 ? 1 / spread.ipr : 0.0);
  if (mle) out.mle.push_back(*mle);
  if (config.energy_map) out.energy_map.insert(out.energy_map.end(), energy.begin(), energy.end());
  out.max_energy_error = std::max(out.max_energy_error, std::abs(total_energy(law, chain, s) - h0) / h0);
}

/// The tangent map of a run with the mLE: its deviation vector starts on the centre bead, norm with
/// time unit 1, renormalized every 10 steps.
constexpr LyapunovConfig klein_gordon_lyapunov{.enabled = true, .renormalize_every = 10, .time_unit = 1};

/// Realizations `rs` of `config` (at most LanePropagator::width()) side by side in vector lanes,
/// each run the same bits as run_klein_gordon's; `maps[i]`: whether rs[i] keeps its energy map.
/// With the mLE a lane whose deviation vector fails throws NumericalError, as run_klein_gordon does.
std::vector<KleinGordonRun> run_klein_gordon_in_lanes(const KleinGordonRunConfig& config,
                                                      std::span<const std::uint64_t> rs, const std::vector<bool>& maps) {
  std::vector<Chain> chains;
  std::vector<State> starts, deviations;
  std::vector<ForceLaw> laws;
  std::vector<double> h0;
  for (const std::uint64_t r : rs) {
    KleinGordonStart k = klein_gordon_start(config, r);
    chains.push_back(std::move(k.chain));
    starts.push_back(std::move(k.start));
    laws.push_back(make_force_law(ForceLawKind::linear, chains.back()));
    h0.push_back(total_energy(laws.back(), chains.back(), starts.back()));
    const std::size_t n = chains.back().size();
    if (config.mle) deviations.push_back(localized_deviation(n, centre_site(n), klein_gordon_lyapunov.time_unit));
  }
  std::vector<KleinGordonRun> out(rs.size());
  KleinGordonRunConfig plain = config, mapped = config;
  plain.energy_map = false, mapped.energy_map = true;
  State s;
  const auto run = [&](auto& lanes, auto&& mle_of) {
    for (const std::uint64_t step : config.sample_steps) {
      if (step > lanes.steps_done()) lanes.advance(static_cast<std::size_t>(step - lanes.steps_done()));
      const double t = static_cast<double>(lanes.steps_done()) * config.time_step;  // Propagator::time()
      for (std::size_t l = 0; l < rs.size(); ++l) {
        lanes.copy_lane(l, s.u, s.v);
        const double mle = mle_of(l, t);
        sample(maps[l] ? mapped : plain, laws[l], chains[l], h0[l], s, t, config.mle ? &mle : nullptr, out[l]);
      }
    }
  };
  if (config.mle) {
    LaneTangentPropagator lanes(laws, chains, saba2c(), config.time_step, starts, deviations, klein_gordon_lyapunov);
    run(lanes, [&](std::size_t l, double t) {
      if (!lanes.failure(l).empty()) throw NumericalError(lanes.failure(l));
      return t > 0 ? lanes.log_stretch(l) / t : 0.0;  // TangentPropagator::mle()
    });
  } else {
    LanePropagator lanes(laws, chains, saba2c(), config.time_step, starts, {.enabled = false});
    run(lanes, [](std::size_t, double) { return 0.0; });
  }
  return out;
}

}  // namespace

KleinGordonRun run_klein_gordon(const KleinGordonRunConfig& config, std::uint64_t realization) {
  validate(config);
  const auto [chain, start] = klein_gordon_start(config, realization);
  const ForceLaw law = make_force_law(ForceLawKind::linear, chain);
  const std::size_t n = chain.size(), centre = centre_site(n);
  std::unique_ptr<Propagator> plain;
  std::unique_ptr<TangentPropagator> tangent;
  if (config.mle)
    tangent =
        make_tangent_propagator(law, chain, saba2c(), config.time_step, start,
                                localized_deviation(n, centre, klein_gordon_lyapunov.time_unit), klein_gordon_lyapunov);
  else plain = make_splitting_propagator(law, chain, saba2c(), config.time_step, start, {.enabled = false});
  Propagator& run = config.mle ? static_cast<Propagator&>(*tangent) : *plain;

  const double h0 = total_energy(law, chain, start);
  KleinGordonRun out;
  std::uint64_t done = 0;
  for (const std::uint64_t step : config.sample_steps) {
    if (step > done) run.advance(static_cast<std::size_t>(step - done));
    done = std::max(done, step);
    const double mle = config.mle ? tangent->mle() : 0.0;
    sample(config, law, chain, h0, run.state(), run.time(), config.mle ? &mle : nullptr, out);
  }
  return out;
}

KleinGordonEnsemble klein_gordon_ensemble(const KleinGordonRunConfig& config, std::size_t count, int threads) {
  validate(config);
  if (count < 1) throw InvalidInput("realizations", ": at least 1");
  KleinGordonEnsemble out;
  out.runs.resize(count);
  KleinGordonRunConfig others = config;  // realization 0's map only: the rest would cost R times the memory
  others.energy_map = false;
  {  // LanePropagator::width() realizations at a time, the rest one by one (threads share them)
    const std::size_t width = LanePropagator::width(), batches = count / width;
    parallel_realizations(batches + count % width, threads, [&](std::size_t b, int) {
      if (b >= batches) {
        const std::size_t r = batches * width + (b - batches);
        out.runs[r] = run_klein_gordon(r == 0 ? config : others, r);
        return;
      }
      std::vector<std::uint64_t> rs(width);
      std::vector<bool> maps(width, false);
      for (std::size_t l = 0; l < width; ++l) rs[l] = b * width + l;
      maps[0] = b == 0 && config.energy_map;
      auto runs = run_klein_gordon_in_lanes(config, rs, maps);
      for (std::size_t l = 0; l < width; ++l) out.runs[rs[l]] = std::move(runs[l]);
    });
  }
  const std::size_t samples = config.sample_steps.size();
  out.time = out.runs.front().time;
  out.m2.assign(samples, 0.0);
  out.participation.assign(samples, 0.0);
  if (config.mle) {
    out.mle.assign(samples, 0.0);
    out.mean_log10_mle.assign(samples, 0.0);
  }
  const double scale = 1 / static_cast<double>(count);
  for (const KleinGordonRun& run : out.runs)  // index order: the same sums for any thread count
    for (std::size_t s = 0; s < samples; ++s) {
      out.m2[s] += run.m2[s] * scale;
      out.participation[s] += run.participation[s] * scale;
      if (config.mle) {
        out.mle[s] += run.mle[s] * scale;
        out.mean_log10_mle[s] +=
            run.mle[s] > 0 ? std::log10(run.mle[s]) * scale : std::numeric_limits<double>::quiet_NaN();
      }
    }
  return out;
}

}  // namespace granular
