// Transfer-matrix kernel: λ and node counts at F frequencies on an N-bead Anderson chain
// (ξ = q = 0.5, F0 = 10 N, seed 1), one thread unless stated. "stored" reads a chain held in
// memory (chain_beads), "streamed" draws the beads from the Philox stream on every pass
// (random_beads); the difference is the cost of generating the chain. Counter ns_per_step is per
// bead per frequency. Whole-process times and the NumPy comparison: localization_vs_numpy.sh.
//   build/benchmarks/localization_benchmark --benchmark_filter=streamed
#include <map>
#include <memory>

#include <benchmark/benchmark.h>

#include "granular/linear/transfer_matrix.hpp"
#include "granular/model/bead_source.hpp"
#include "granular/model/disorder.hpp"

namespace {

using namespace granular;

std::vector<double> frequencies(std::size_t count) {
  std::vector<double> f(count);
  for (std::size_t k = 0; k < count; ++k) f[k] = 50.0 * static_cast<double>(k + 1) / static_cast<double>(count);
  return f;
}

const BeadSource& stored(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<BeadSource>> cache;
  auto& p = cache[n];
  if (!p)
    p = chain_beads(
        make_chain(radii_of(realization_configuration(Disorder::anderson, 0.5, n, 1, 0), 4.76e-3, 0.5), 10.0));
  return *p;
}

void run(benchmark::State& state, const BeadSource& chain, int threads) {
  const auto f = frequencies(static_cast<std::size_t>(state.range(0)));
  TransferMatrixConfig config;
  config.threads = threads;
  for (auto _ : state) {
    auto scan = transfer_matrix_scan(chain, f, config);
    benchmark::DoNotOptimize(scan.lyapunov.data());
  }
  const double steps = static_cast<double>(chain.size()) * static_cast<double>(f.size());
  state.counters["ns_per_step"] =
      benchmark::Counter(steps * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void streamed(benchmark::State& state) {
  const auto chain =
      random_beads(Disorder::anderson,
                   {.N = static_cast<std::size_t>(state.range(1)), .q = 0.5, .seed = 1, .realization = 0});
  run(state, *chain, 1);
}
void streamed_two_threads(benchmark::State& state) {
  const auto chain =
      random_beads(Disorder::anderson,
                   {.N = static_cast<std::size_t>(state.range(1)), .q = 0.5, .seed = 1, .realization = 0});
  run(state, *chain, 2);
}
void stored_chain(benchmark::State& state) { run(state, stored(static_cast<std::size_t>(state.range(1))), 1); }

/// The bead source alone: one pass over the chain in the kernel's pieces.
void generate(benchmark::State& state) {
  const auto chain =
      random_beads(Disorder::anderson,
                   {.N = static_cast<std::size_t>(state.range(0)), .q = 0.5, .seed = 1, .realization = 0});
  std::vector<double> m(1024), b(1025);
  for (auto _ : state)
    for (std::size_t p = 0; p < chain->size(); p += 1024) {
      chain->read(p, std::min<std::size_t>(1024, chain->size() - p), m.data(), b.data());
      benchmark::DoNotOptimize(m.data());
    }
  state.counters["ns_per_bead"] =
      benchmark::Counter(static_cast<double>(state.range(0)) * 1e-9,
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(streamed)
    ->Args({1, 1000000})
    ->Args({16, 1000000})
    ->Args({64, 1000000})
    ->Args({1000, 1000000})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(stored_chain)->Args({64, 1000000})->Args({1000, 1000000})->Unit(benchmark::kMillisecond);
BENCHMARK(streamed_two_threads)->Args({1000, 1000000})->Args({1000, 10000000})->Unit(benchmark::kMillisecond);
BENCHMARK(generate)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
