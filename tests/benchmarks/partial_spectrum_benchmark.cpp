// Partial spectra: K = 20 modes nearest 15 kHz of an Anderson chain (ξ = q = 0.5,
// F0 = 10 N, seed 1, realization 0), solver time only (the matrix is built once per N), for each
// method and N. Whole-process times, peak memory and SciPy side by side: partial_spectrum_scaling.sh.
//   build/benchmarks/partial_spectrum_benchmark --benchmark_filter='bisect'
#include <map>
#include <memory>

#include <benchmark/benchmark.h>

#include "granular/linear/detail/shift_invert_eigensolvers.hpp"
#include "granular/linear/detail/sturm_bisection.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/linear/tridiagonal_operator.hpp"
#include "granular/model/named_chains.hpp"

namespace {

using namespace granular;

struct Problem {
  DynamicalMatrix t;
};

const Problem& problem(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<Problem>> cache;
  auto& p = cache[n];
  if (!p) p = std::make_unique<Problem>(Problem{dynamical_matrix(anderson({.N = n, .q = 0.5, .xi = 0.5, .seed = 1}))});
  return *p;
}

void run(benchmark::State& state, SpectrumMethod method) {
  const auto& p = problem(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    auto r = spectrum(p.t, nearest(15.0, 20), {.method = method});
    benchmark::DoNotOptimize(r.ipr.data());
  }
  state.counters["ns_per_bead"] =
      benchmark::Counter(static_cast<double>(state.range(0)),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_partial_bisect(benchmark::State& s) { run(s, SpectrumMethod::bisect); }
void BM_partial_lapack(benchmark::State& s) { run(s, SpectrumMethod::lapack); }
void BM_partial_arpack(benchmark::State& s) { run(s, SpectrumMethod::arpack); }
void BM_partial_slepc(benchmark::State& s) { run(s, SpectrumMethod::slepc); }

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

BENCHMARK(BM_partial_bisect)
    ->Arg(100000)
    ->Arg(1000000)
    ->Arg(10000000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
BENCHMARK(BM_partial_lapack)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_partial_arpack)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_partial_slepc)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_count_below_1_shift)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_count_below_32_shifts)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_shift_invert_factorize)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
