// Speed of the dynamics: the bare bond kernel, the SABA2C step, one realization of
// the paper's problem (N = 2501, τ = 1 µs, T = 10 ms, F0 = 10 N, displacement kick, one Anderson
// chain ξ = q = 0.5, seed 1 realization 0) with and without the active window against Boost.Odeint's
// symplectic_rkn_sb3a_mclachlan at the same τ, and the cost–accuracy of every scheme.
// Results and commands: docs/performance.md, "Dynamics: speed and accuracy".
#include <algorithm>
#include <cmath>
#include <ctime>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>
#include <boost/numeric/odeint.hpp>

#include "granular/chaos/lyapunov_spectrum.hpp"
#include "granular/dynamics/damping.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/tangent_map.hpp"
#include "granular/lanes/lane_propagator.hpp"
#include "granular/lanes/lane_tangent_propagator.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"

namespace {

using namespace granular;

constexpr std::size_t beads = 2501;
constexpr double tau = 1e-6, duration = 1e-2;

const Chain& paper_chain() {
  static const Chain chain =
      make_chain(radii_of(realization_configuration(Disorder::anderson, 0.5, beads, 1, 0), 4.76e-3, 0.5), 10.0);
  return chain;
}
const ForceLaw& paper_law() {
  static const ForceLaw law = make_force_law(ForceLawKind::hertz, paper_chain());
  return law;
}
const State& paper_kick() {
  static const State s = displacement_kick(paper_chain(), centre_site(beads), 1e-7);
  return s;
}

// The reference final state (Odeint RKF78 at 1e-16, smooth case): computed once, ~seconds.
const std::vector<double>& reference_final() {
  static const std::vector<double> u = [] {
    auto p = make_reference_propagator(paper_law(), paper_chain(), tau, paper_kick(), {1e-16, 1e-16, 0});
    p->advance(static_cast<std::size_t>(std::llround(duration / tau)));
    return std::vector<double>(p->displacement().begin(), p->displacement().end());
  }();
  return u;
}

double relative_difference(std::span<const double> a, const std::vector<double>& b) {
  double d = 0, s = 0;
  for (std::size_t i = 0; i < b.size(); ++i) d += (a[i] - b[i]) * (a[i] - b[i]), s += b[i] * b[i];
  return std::sqrt(d / s);
}

// The bare kernel: f_k = A_k [Δ_k + u_{k−1} − u_k]_+^{3/2} over N+1 bonds, exact sqrt.
void BM_BareBondKernel(benchmark::State& state) {
  const Chain& c = paper_chain();
  std::vector<double> u(beads + 2, 0.0), f(beads + 1);
  for (std::size_t i = 1; i <= beads; ++i) u[i] = 1e-8 * std::sin(0.1 * static_cast<double>(i));
  const double* __restrict a = c.contact.data();
  const double* __restrict d0 = c.overlap.data();
  const double* __restrict up = u.data();
  double* __restrict fp = f.data();
  for (auto _ : state) {
    for (std::size_t k = 0; k <= beads; ++k) {
      const double d = std::max(d0[k] + up[k] - up[k + 1], 0.0);
      fp[k] = a[k] * d * std::sqrt(d);
    }
    benchmark::DoNotOptimize(fp);
    benchmark::ClobberMemory();
  }
  state.counters["bonds_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * (beads + 1), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BareBondKernel);

// Whole SABA2C steps on the full chain (window off): bond force evaluations per second.
void BM_Saba2cStep(benchmark::State& state) {
  auto p = make_splitting_propagator(paper_law(), paper_chain(), saba2c(), tau, paper_kick(), {false});
  p->advance(2000);  // a developed wave, not the initial single bead
  const auto before = p->bond_updates();
  for (auto _ : state) p->advance(100);
  state.counters["bond_updates_per_s"] =
      benchmark::Counter(static_cast<double>(p->bond_updates() - before), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Saba2cStep)->Unit(benchmark::kMicrosecond);

// The budget: a damped step and a tangent-map step at most 2× BM_Saba2cStep (whole chain, 100 steps
// per iteration each).
// Arg 0: on-site damping only (exact flow); 1: Kuwabara–Kono too (parity-split pair steps).
void BM_DampedSaba2cStep(benchmark::State& state) {
  // Weak damping, so that a long benchmark does not run into denormal velocities; the cost is the same.
  const Damping damping{1.0, state.range(0) ? 1e-9 : 0.0};
  auto p = make_damped_propagator(paper_law(), paper_chain(), saba2c(), tau, paper_kick(), damping);
  p->advance(1000);                      // leave the initial transient
  for (auto _ : state) p->advance(100);  // 100 steps per iteration, as BM_Saba2cStep
}
BENCHMARK(BM_DampedSaba2cStep)->Arg(0)->Arg(1)->ArgName("kk")->Unit(benchmark::kMicrosecond);

void BM_TangentSaba2cStep(benchmark::State& state) {
  auto p = make_tangent_propagator(paper_law(), paper_chain(), saba2c(), tau, paper_kick(),
                                   localized_deviation(beads, centre_site(beads)));
  p->advance(1000);
  const auto before = p->bond_updates();
  for (auto _ : state) p->advance(100);  // 100 steps per iteration, as BM_Saba2cStep
  state.counters["bond_updates_per_s"] =
      benchmark::Counter(static_cast<double>(p->bond_updates() - before), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_TangentSaba2cStep)->Unit(benchmark::kMicrosecond);

// The same three budgets as ratios robust to load: each iteration runs 100 conservative SABA2C
// steps (BM_Saba2cStep) and then 100 steps of the variant, each timed by this thread's CPU clock,
// so both see the same machine within milliseconds; `ratio` = variant time / conservative time.
// Arg 0: on-site damping; 1: on-site + Kuwabara–Kono; 2: Kuwabara–Kono alone; 3: the tangent map;
// 4, 5: Kuwabara–Kono alone with γ_KK = 1e-6 s and 1e-5 s (calibrated steel beads take 1e-7 …
// 1e-5 s: docs/beyond-the-paper.md). Arms 1 and 2 take γ_KK = 1e-9 s, as they always did. The
// cost depends on γ_KK only through e^x − 1: the short series serves every contact with a loss
// rate y ≤ 1/32 per step (all of them up to 1e-6 s here), the whole formula a block of bonds
// with one beyond (light beads at 1e-5 s).
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void BM_CostRatioToSaba2c(benchmark::State& state) {
  auto base = make_splitting_propagator(paper_law(), paper_chain(), saba2c(), tau, paper_kick(), {false});
  std::unique_ptr<Propagator> variant;
  const auto which = state.range(0);
  if (which == 3)
    variant = make_tangent_propagator(paper_law(), paper_chain(), saba2c(), tau, paper_kick(),
                                      localized_deviation(beads, centre_site(beads)));
  else
    variant = make_damped_propagator(paper_law(), paper_chain(), saba2c(), tau, paper_kick(),
                                     Damping{which == 1 || which == 0 ? 1.0 : 0.0, which == 0   ? 0.0
                                                                                   : which == 4 ? 1e-6
                                                                                   : which == 5 ? 1e-5
                                                                                                : 1e-9});
  base->advance(1000);
  variant->advance(1000);
  double base_time = 0, variant_time = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    base->advance(100);
    const double t1 = thread_seconds();
    variant->advance(100);
    const double t2 = thread_seconds();
    base_time += t1 - t0;
    variant_time += t2 - t1;
  }
  const double steps = 100.0 * static_cast<double>(state.iterations());
  static const char* const label[] = {"on-site", "on-site+kk", "kk", "tangent", "kk 1e-6 s", "kk 1e-5 s"};
  state.SetLabel(label[which]);
  state.counters["ratio"] = variant_time / base_time;
  state.counters["us_per_step"] = 1e6 * variant_time / steps;
  state.counters["saba2c_us_per_step"] = 1e6 * base_time / steps;
}
BENCHMARK(BM_CostRatioToSaba2c)->DenseRange(0, 5)->ArgName("variant")->Unit(benchmark::kMillisecond)->MinTime(1.0);

// The Lyapunov spectrum's cost per vector (issue 44's budget: k vectors at most (1 + 0.7 k) × a
// plain step, plus the QR): k deviation vectors on the tangent map, re-orthonormalized by QR every
// 10 steps, against plain SABA2C steps interleaved as above (CPU time of this thread). `ratio` is
// the spectrum's step over a plain step; `budget` is 1 + 0.7 k.
void BM_LyapunovSpectrumCostRatio(benchmark::State& state) {
  const auto k = static_cast<std::size_t>(state.range(0));
  auto base = make_splitting_propagator(paper_law(), paper_chain(), saba2c(), tau, paper_kick(), {false});
  LyapunovSpectrum spectrum(paper_law(), paper_chain(), saba2c(), tau, paper_kick(),
                            {.vectors = k, .orthonormalize_every = 10});
  base->advance(1000);
  spectrum.advance(1000);
  double base_time = 0, spectrum_time = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    base->advance(100);
    const double t1 = thread_seconds();
    spectrum.advance(100);
    const double t2 = thread_seconds();
    base_time += t1 - t0;
    spectrum_time += t2 - t1;
  }
  const double steps = 100.0 * static_cast<double>(state.iterations());
  state.counters["ratio"] = spectrum_time / base_time;
  state.counters["budget"] = 1 + 0.7 * static_cast<double>(k);
  state.counters["us_per_step"] = 1e6 * spectrum_time / steps;
  state.counters["saba2c_us_per_step"] = 1e6 * base_time / steps;
}
BENCHMARK(BM_LyapunovSpectrumCostRatio)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->ArgName("vectors")
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

// One realization: 10 000 steps of SABA2C, with or without the active window; the energy error
// is the max over 100 uniform samples (which also cost 100 extra corrector kicks).
void BM_RealizationSaba2c(benchmark::State& state) {
  const bool window = state.range(0) != 0;
  double error = 0, state_error = 0;
  for (auto _ : state) {
    auto p = make_splitting_propagator(paper_law(), paper_chain(), saba2c(), tau, paper_kick(), {window});
    p->advance(10000);
    benchmark::DoNotOptimize(p->displacement().data());
    state.PauseTiming();
    const double h0 = total_energy(paper_law(), paper_chain(), paper_kick());
    error = std::abs(total_energy(paper_law(), paper_chain(), p->state()) - h0) / h0;
    state_error = relative_difference(p->displacement(), reference_final());
    state.ResumeTiming();
  }
  state.counters["final_energy_error"] = error;
  state.counters["final_state_error"] = state_error;
}
BENCHMARK(BM_RealizationSaba2c)->Arg(0)->Arg(1)->ArgName("window")->Unit(benchmark::kMillisecond)->MinTime(2.0);

// The same in vector lanes (lane_propagator.hpp): W = LanePropagator::width() realizations of the
// paper's problem side by side (Anderson seed 1, realizations 0 … W − 1), so that a lane's rate
// compares with BM_Saba2cStep and BM_BareBondKernel, and the time per realization with
// BM_RealizationSaba2c.
struct PaperLanes {
  std::vector<Chain> chains;
  std::vector<ForceLaw> laws;
  std::vector<State> kicks;
  explicit PaperLanes(std::size_t n) {
    for (std::size_t l = 0; l < LanePropagator::width(); ++l) {
      chains.push_back(
          make_chain(radii_of(realization_configuration(Disorder::anderson, 0.5, n, 1, l), 4.76e-3, 0.5), 10.0));
      laws.push_back(make_force_law(ForceLawKind::hertz, chains.back()));
      kicks.push_back(displacement_kick(chains.back(), centre_site(n), 1e-7));
    }
  }
};
const PaperLanes& paper_lanes() {
  static const PaperLanes lanes(beads);
  return lanes;
}

// Whole SABA2C steps on the full chains (window off): bond force evaluations per second per lane.
// Arg: the chains' length (the paper's 2501; 401 keeps the W chains' arrays in L2).
void BM_LaneSaba2cStep(benchmark::State& state) {
  const PaperLanes b(static_cast<std::size_t>(state.range(0)));
  LanePropagator p(b.laws, b.chains, saba2c(), tau, b.kicks, {false});
  p.advance(2000);
  const auto before = p.bond_updates(0);
  for (auto _ : state) p.advance(100);
  state.counters["bond_updates_per_s_per_lane"] =
      benchmark::Counter(static_cast<double>(p.bond_updates(0) - before), benchmark::Counter::kIsRate);
  state.counters["lanes"] = static_cast<double>(LanePropagator::width());
}
BENCHMARK(BM_LaneSaba2cStep)->Arg(beads)->Arg(401)->ArgName("beads")->Unit(benchmark::kMicrosecond);

// BM_TangentSaba2cStep in vector lanes (lane_tangent_propagator.hpp): W orbits of the paper's
// problem, each with its deviation vector, 100 steps per iteration; bond updates per second per lane.
void BM_LaneTangentSaba2cStep(benchmark::State& state) {
  const PaperLanes& b = paper_lanes();
  const std::vector<State> deviations(b.chains.size(), localized_deviation(beads, centre_site(beads)));
  LaneTangentPropagator p(b.laws, b.chains, saba2c(), tau, b.kicks, deviations, {.enabled = true});
  p.advance(1000);
  const auto before = p.bond_updates(0);
  for (auto _ : state) p.advance(100);
  state.counters["bond_updates_per_s_per_lane"] =
      benchmark::Counter(static_cast<double>(p.bond_updates(0) - before), benchmark::Counter::kIsRate);
  state.counters["lanes"] = static_cast<double>(LaneTangentPropagator::width());
}
BENCHMARK(BM_LaneTangentSaba2cStep)->Unit(benchmark::kMicrosecond);

// W realizations of BM_RealizationSaba2c side by side: the time per realization is this / W.
void BM_LaneRealizationsSaba2c(benchmark::State& state) {
  const bool window = state.range(0) != 0;
  const PaperLanes& b = paper_lanes();
  for (auto _ : state) {
    LanePropagator p(b.laws, b.chains, saba2c(), tau, b.kicks, {window});
    p.advance(10000);
    benchmark::DoNotOptimize(p.steps_done());
  }
  state.counters["lanes"] = static_cast<double>(LanePropagator::width());  // realizations per iteration
}
BENCHMARK(BM_LaneRealizationsSaba2c)->Arg(0)->Arg(1)->ArgName("window")->Unit(benchmark::kMillisecond)->MinTime(2.0);

// Boost.Odeint's 4th-order symplectic RKN (McLachlan sb3a) with the same Hertz force kernel.
class OdeintSb3a {
 public:
  using Vector = std::vector<double>;
  OdeintSb3a() : q_(paper_kick().u), v_(paper_kick().v), f_(beads + 1), padded_(beads + 2, 0.0) {}
  void advance(std::size_t steps, double step) {
    const Chain& c = paper_chain();
    const auto law = std::get<HertzLaw>(paper_law()).view();
    auto force = [&](const Vector& q, Vector& dvdt) {
      std::copy(q.begin(), q.end(), padded_.begin() + 1);
      const double* __restrict u = padded_.data();
      double* __restrict fk = f_.data();
      for (std::size_t k = 0; k <= beads; ++k) fk[k] = law.force(k, u[k] - u[k + 1]);
      const double* __restrict im = c.inverse_mass.data();
      double* __restrict a = dvdt.data();
      for (std::size_t i = 0; i < beads; ++i) a[i] = im[i] * (fk[i] - fk[i + 1]);
    };
    for (std::size_t s = 0; s < steps; ++s, t_ += step)
      stepper_.do_step(force, std::make_pair(std::ref(q_), std::ref(v_)), t_, step);
  }
  State state() const {
    State s;
    s.u = q_;
    s.v = v_;
    return s;
  }
  const Vector& displacement() const { return q_; }

 private:
  Vector q_, v_, f_, padded_;
  double t_ = 0;
  boost::numeric::odeint::symplectic_rkn_sb3a_mclachlan<Vector> stepper_;
};

void BM_RealizationOdeintSb3a(benchmark::State& state) {
  double error = 0, state_error = 0;
  for (auto _ : state) {
    OdeintSb3a o;
    o.advance(10000, tau);
    state.PauseTiming();
    const double h0 = total_energy(paper_law(), paper_chain(), paper_kick());
    error = std::abs(total_energy(paper_law(), paper_chain(), o.state()) - h0) / h0;
    state_error = relative_difference(o.displacement(), reference_final());
    state.ResumeTiming();
  }
  state.counters["final_energy_error"] = error;
  state.counters["final_state_error"] = state_error;
}
BENCHMARK(BM_RealizationOdeintSb3a)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// Odeint's sb3a on the cost–accuracy curve, measured exactly like the schemes below.
void BM_CostAccuracyOdeint(benchmark::State& state) {
  const double step = static_cast<double>(state.range(0)) * 1e-9;
  const auto steps = static_cast<std::size_t>(std::llround(duration / step));
  const double h0 = total_energy(paper_law(), paper_chain(), paper_kick());
  double max_error = 0, state_error = 0;
  for (auto _ : state) {
    OdeintSb3a o;
    max_error = 0;
    for (std::size_t k = 1, done = 0; k <= 100; ++k) {
      o.advance(steps * k / 100 - done, step);
      done = steps * k / 100;
      state.PauseTiming();
      max_error = std::max(max_error, std::abs(total_energy(paper_law(), paper_chain(), o.state()) - h0) / h0);
      state.ResumeTiming();
    }
    state.PauseTiming();
    state_error = relative_difference(o.displacement(), reference_final());
    state.ResumeTiming();
  }
  state.SetLabel("odeint sb3a");
  state.counters["max_energy_error"] = max_error;
  state.counters["final_state_error"] = state_error;
}
BENCHMARK(BM_CostAccuracyOdeint)
    ->ArgName("tau_ns")
    ->Arg(2000)
    ->Arg(1000)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

// Cost–accuracy: every scheme at several τ (ns in the argument), window off so that the schemes
// alone are compared; max energy error over 100 uniform samples and the final-state error
// against the RKF78 reference.
void BM_CostAccuracy(benchmark::State& state) {
  const SplittingScheme schemes[] = {saba2c(), aba864(), srkn14a()};
  const SplittingScheme& scheme = schemes[state.range(0)];
  const double step = static_cast<double>(state.range(1)) * 1e-9;
  const auto steps = static_cast<std::size_t>(std::llround(duration / step));
  const double h0 = total_energy(paper_law(), paper_chain(), paper_kick());
  double max_error = 0, state_error = 0;
  for (auto _ : state) {
    auto p = make_splitting_propagator(paper_law(), paper_chain(), scheme, step, paper_kick(), {false});
    max_error = 0;
    for (std::size_t k = 1; k <= 100; ++k) {
      p->advance(steps * k / 100 - p->steps_done());
      state.PauseTiming();
      max_error = std::max(max_error, std::abs(total_energy(paper_law(), paper_chain(), p->state()) - h0) / h0);
      state.ResumeTiming();
    }
    state.PauseTiming();
    state_error = relative_difference(p->displacement(), reference_final());
    state.ResumeTiming();
  }
  state.SetLabel(scheme.name);
  state.counters["max_energy_error"] = max_error;
  state.counters["final_state_error"] = state_error;
}
BENCHMARK(BM_CostAccuracy)
    ->ArgNames({"scheme", "tau_ns"})
    ->ArgsProduct({{0}, {2000, 1000, 500, 250}})
    ->ArgsProduct({{1}, {4000, 2000, 1000, 500}})
    ->ArgsProduct({{2}, {8000, 4000, 2000, 1000}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

}  // namespace

BENCHMARK_MAIN();
