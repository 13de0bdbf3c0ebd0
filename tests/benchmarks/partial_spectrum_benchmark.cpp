// Partial spectra (issue 3): K = 20 modes nearest 15 kHz of an Anderson chain (ξ = q = 0.5,
// F0 = 10 N, seed 1, realization 0), solver time only (the matrix is built once per N), for each
// method and N. Whole-process times, peak memory and SciPy side by side: partial_spectrum_scaling.sh.
//   build/benchmarks/partial_spectrum_benchmark --benchmark_filter='bisect'
#include <map>
#include <memory>

#include <benchmark/benchmark.h>

#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/linear/partial_spectrum.hpp"
#include "granular/linear/shift_invert_eigensolvers.hpp"
#include "granular/linear/sturm_bisection.hpp"
#include "granular/linear/tridiagonal_operator.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"

namespace {

using namespace granular;

struct Problem {
  SymTridiagonal t;
  std::vector<double> s;
};

const Problem& problem(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<Problem>> cache;
  auto& p = cache[n];
  if (!p) {
    const auto types = realization_configuration(Disorder::anderson, 0.5, n, 1, 0);
    const Chain chain = make_chain(radii_of(types, 4.76e-3, 0.5), 10.0);
    p = std::make_unique<Problem>(Problem{dynamical_matrix(chain), inverse_sqrt_mass(chain.inverse_mass)});
  }
  return *p;
}

void run(benchmark::State& state, PartialMethod method) {
  const auto& p = problem(static_cast<std::size_t>(state.range(0)));
  PartialSpectrumConfig config;
  config.method = method;
  for (auto _ : state) {
    auto r = partial_spectrum(p.t, p.s, SpectrumSelection::nearest(15.0, 20), config);
    benchmark::DoNotOptimize(r.ipr.data());
  }
  state.counters["ns_per_bead"] =
      benchmark::Counter(static_cast<double>(state.range(0)), benchmark::Counter::kIsIterationInvariantRate |
                                                                   benchmark::Counter::kInvert);
}

void BM_partial_bisect(benchmark::State& s) { run(s, PartialMethod::bisect); }
void BM_partial_lapack(benchmark::State& s) { run(s, PartialMethod::lapack); }
void BM_partial_arpack(benchmark::State& s) { run(s, PartialMethod::arpack); }
void BM_partial_slepc(benchmark::State& s) { run(s, PartialMethod::slepc); }

// The building blocks, per sweep over the matrix.
void BM_count_below_1_shift(benchmark::State& state) {
  const auto& p = problem(static_cast<std::size_t>(state.range(0)));
  const TridiagonalOperator op(p.t);
  for (auto _ : state) benchmark::DoNotOptimize(op.count_below(omega_squared_of_khz(15)));
}
void BM_count_below_32_shifts(benchmark::State& state) {
  const auto& p = problem(static_cast<std::size_t>(state.range(0)));
  std::vector<double> shifts(32);
  for (int j = 0; j < 32; ++j) shifts[j] = omega_squared_of_khz(15 + 0.01 * j);
  for (auto _ : state) benchmark::DoNotOptimize(count_below_many(p.t, shifts).data());
}
void BM_shift_invert_factorize(benchmark::State& state) {
  const auto& p = problem(static_cast<std::size_t>(state.range(0)));
  ShiftInvertOperator op;
  for (auto _ : state) op.factorize(p.t, omega_squared_of_khz(15));
}

}  // namespace

BENCHMARK(BM_partial_bisect)->Arg(100000)->Arg(1000000)->Arg(10000000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_partial_lapack)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_partial_arpack)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_partial_slepc)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_count_below_1_shift)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_count_below_32_shifts)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_shift_invert_factorize)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
