// Per-solve cost of "ω² and the IPR of every mode" on the default ipr-map job's chains:
// Anderson disorder, N = 100, F0 = 10 N, every (q, ξ) cell of q = 0.2/0.5/0.8 × ξ = 0.1:1:0.01,
// a few realizations each (the same configurations ipr-map draws with seed 1). One benchmark
// iteration solves one chain; the chains are cycled so every cell is visited.
//
//   build/benchmarks/ipr_map_benchmark --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//
// BM_ModeIpr/<solver>: the solvers behind `ipr-map --solver` (LAPACK drivers with eigenvectors,
// then Σv⁴/(Σv²)²; the fast twisted-factorization solver), one chain per call.
// BM_ModeIprBatch/<solver>_batch/N/B: B chains per solve_batch call, as ipr-map calls it.
// BM_EigenvaluesOnly/dsterf and /dqds: the O(N²) eigenvalue floor under any solver that needs every
// mode (LAPACK's root-free QL, and dqds — dlasq2 on T's L D Lᵀ —, the fastest eigenvalue-only
// algorithm LAPACK has). BM_BuildChain: making the chain and its dynamical matrix, the
// per-realization cost outside any solver. The `_N1000` rows are the same at N = 1000 (ipr-map
// --N 1000), one realization per cell: how far a 1000-bead map is from its floor.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "granular/linear/detail/lapack.hpp"
#include "granular/linear/detail/mode_ipr_solver.hpp"
#include "granular/linear/detail/rational_ql.hpp"
#include "granular/linear/detail/twisted_ipr_solver.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/disorder.hpp"

namespace {

using namespace granular;

extern "C" void dlasq2_(const int* n, double* z, int* info);

struct Job {
  std::vector<SymTridiagonal> matrices;
  std::vector<std::vector<double>> inverse_sqrt_masses;
  std::vector<std::vector<double>> radii;
};

Job make_job(std::size_t beads, std::size_t realizations_per_cell) {
  Job j;
  for (double q : {0.2, 0.5, 0.8})
    for (int step = 0; step <= 90; ++step) {
      const double xi = 0.1 + 0.01 * step;
      for (std::size_t r = 0; r < realizations_per_cell; ++r) {
        const auto types = realization_configuration(Disorder::anderson, q, beads, 1, r);
        j.radii.push_back(radii_of(types, 4.76e-3, xi));
        const Chain chain = make_chain(j.radii.back(), 10.0);
        j.matrices.push_back(dynamical_matrix(chain));
        j.inverse_sqrt_masses.push_back(inverse_sqrt_mass(chain.inverse_mass));
      }
    }
  return j;
}

/// The default job's chains (N = 100, 4 realizations per cell) or its N = 1000 version (1 per cell).
const Job& job_of(std::size_t beads) {
  if (beads == 100) {
    static const Job small = make_job(100, 4);
    return small;
  }
  static const Job large = make_job(1000, 1);
  return large;
}

void BM_ModeIpr(benchmark::State& state, std::string method) {
  const Job& job = job_of(static_cast<std::size_t>(state.range(0)));
  auto solver = make_mode_ipr_solver(method);
  std::vector<double> omega2, ipr;
  std::size_t i = 0;
  for (auto _ : state) {
    solver->solve(job.matrices[i], job.inverse_sqrt_masses[i], omega2, ipr);
    benchmark::DoNotOptimize(ipr.data());
    if (++i == job.matrices.size()) i = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  if (auto* fast = dynamic_cast<TwistedModeIpr*>(solver.get())) {
    const auto& info = fast->info();
    state.counters["cluster_modes_per_solve"] =
        static_cast<double>(info.cluster_modes) / static_cast<double>(info.solves);
    state.counters["fallbacks"] = static_cast<double>(info.fallbacks);
  }
}

// range(1) chains per solve_batch call, as ipr-map calls it (the fast solver runs their QL
// iterations in vector lanes); us_per_chain = time per iteration / batch.
void BM_ModeIprBatch(benchmark::State& state, std::string method) {
  const Job& job = job_of(static_cast<std::size_t>(state.range(0)));
  auto solver = make_mode_ipr_solver(method);
  const auto batch = static_cast<std::size_t>(state.range(1));
  std::vector<std::vector<double>> omega2(batch), ipr(batch);
  std::vector<ModeIprTask> tasks(batch);
  std::size_t i = 0;
  for (auto _ : state) {
    for (std::size_t j = 0; j < batch; ++j) {
      tasks[j] = {&job.matrices[i], &job.inverse_sqrt_masses[i], &omega2[j], &ipr[j]};
      if (++i == job.matrices.size()) i = 0;
    }
    solver->solve_batch(tasks);
    benchmark::DoNotOptimize(ipr[0].data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * batch));
  state.counters["us_per_chain"] = benchmark::Counter(static_cast<double>(state.iterations() * batch),
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// dsterf on T / max|T_ij|, or dqds: dlasq2 on the qd array (q_i = D_i, e_i = l_i² D_i) of T = L D Lᵀ
// (T is positive definite for F0 > 0), the representation dstemr starts from.
void BM_EigenvaluesOnly(benchmark::State& state, bool dqds) {
  const std::size_t beads = static_cast<std::size_t>(state.range(0));
  const Job& job = job_of(beads);
  std::vector<double> d(beads), e(beads), z(4 * beads);
  const int n = static_cast<int>(beads);
  std::size_t i = 0;
  for (auto _ : state) {
    const SymTridiagonal& t = job.matrices[i];
    const double inv = 1.0 / t.max_abs();
    for (std::size_t k = 0; k < beads; ++k) d[k] = t.diagonal[k] * inv;
    for (std::size_t k = 0; k + 1 < beads; ++k) e[k] = t.off_diagonal[k] * inv;
    int info = 0;
    if (dqds) {
      double pivot = d[0];
      for (std::size_t k = 0; k + 1 < beads; ++k) {
        const double l = e[k] / pivot;
        z[2 * k] = pivot;
        z[2 * k + 1] = l * l * pivot;
        pivot = d[k + 1] - l * e[k];
      }
      z[2 * beads - 2] = pivot;
      dlasq2_(&n, z.data(), &info);
      benchmark::DoNotOptimize(z.data());
    } else {
      dsterf_(&n, d.data(), e.data(), &info);
      benchmark::DoNotOptimize(d.data());
    }
    if (info != 0) state.SkipWithError("eigenvalues failed");
    if (++i == job.matrices.size()) i = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

// The fast solver's eigenvalue phase alone: rational_ql on one chain per call, or
// rational_ql_lanes on range(1) chains per call (their QL iterations in vector lanes).
void BM_RationalQl(benchmark::State& state) {
  const auto beads = static_cast<std::size_t>(state.range(0)), batch = static_cast<std::size_t>(state.range(1));
  const Job& job = job_of(beads);
  std::vector<std::vector<double>> d(batch, std::vector<double>(beads)), e2(batch, std::vector<double>(beads));
  std::vector<detail::QlChain> chains(batch);
  detail::QlLaneWork work;
  std::size_t i = 0;
  for (auto _ : state) {
    for (std::size_t j = 0; j < batch; ++j) {
      const SymTridiagonal& t = job.matrices[i];
      const double inv = 1.0 / t.max_abs();
      for (std::size_t k = 0; k < beads; ++k) d[j][k] = t.diagonal[k] * inv;
      for (std::size_t k = 0; k + 1 < beads; ++k) e2[j][k] = (t.off_diagonal[k] * inv) * (t.off_diagonal[k] * inv);
      chains[j] = {d[j].data(), e2[j].data(), beads};
      if (++i == job.matrices.size()) i = 0;
    }
    if (batch == 1) detail::rational_ql(chains[0]);
    else detail::rational_ql_lanes(chains, work);
    benchmark::DoNotOptimize(d[0].data());
  }
  state.counters["us_per_chain"] = benchmark::Counter(static_cast<double>(state.iterations() * batch),
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_BuildChain(benchmark::State& state) {
  const Job& job = job_of(100);
  std::size_t i = 0;
  for (auto _ : state) {
    const Chain chain = make_chain(job.radii[i], 10.0);
    auto d = dynamical_matrix(chain);
    auto s = inverse_sqrt_mass(chain.inverse_mass);
    benchmark::DoNotOptimize(d.diagonal.data());
    benchmark::DoNotOptimize(s.data());
    if (++i == job.radii.size()) i = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

}  // namespace

BENCHMARK_CAPTURE(BM_ModeIpr, lapack_stevr, std::string("lapack-stevr"))->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModeIpr, lapack_stemr, std::string("lapack-stemr"))->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModeIpr, lapack_stevd, std::string("lapack-stevd"))->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModeIpr, lapack_steqr, std::string("lapack-steqr"))->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModeIpr, fast, std::string("fast"))->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModeIprBatch, lapack_stevd_batch, std::string("lapack-stevd"))
    ->Args({100, 4})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModeIprBatch, fast_batch, std::string("fast"))
    ->Args({100, 4})
    ->Args({100, 16})
    ->Args({100, 32})
    ->Args({100, 50})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EigenvaluesOnly, dsterf, false)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_EigenvaluesOnly, dqds, true)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RationalQl)->Args({100, 1})->Args({100, 32})->Args({1000, 1})->Args({1000, 32})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BuildChain)->Unit(benchmark::kMicrosecond);
// N = 1000 (the 30 s map of 27,300 chains on 2 cores needs ≤ 2.2 ms of CPU per chain).
BENCHMARK_CAPTURE(BM_ModeIpr, lapack_stevd_N1000, std::string("lapack-stevd"))->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModeIpr, fast_N1000, std::string("fast"))->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModeIprBatch, fast_batch_N1000, std::string("fast"))
    ->Args({1000, 4})
    ->Args({1000, 32})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EigenvaluesOnly, dsterf_N1000, false)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EigenvaluesOnly, dqds_N1000, true)->Arg(1000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
