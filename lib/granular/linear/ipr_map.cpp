#include "granular/linear/ipr_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/error.hpp"
#include "granular/io/number_format.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/linear/mode_ipr_solver.hpp"
#include "granular/model/chain.hpp"

namespace granular {

void validate(const IprMapConfig& c) {
  if (c.n < 2) throw InvalidInput("--N " + std::to_string(c.n) + ": a chain needs at least 2 beads");
  if (!(c.precompression > 0) || !std::isfinite(c.precompression))
    throw InvalidInput("--F0 " + format_number(c.precompression) + ": the linear spectrum needs a finite F0 > 0");
  if (c.realizations < 1) throw InvalidInput("--realizations: must be >= 1");
  if (c.q_values.empty()) throw InvalidInput("--q: no values");
  if (c.xi_values.empty()) throw InvalidInput("--xi: no values");
  for (double q : c.q_values) validate_probability(q);
  for (double xi : c.xi_values) validate_size_ratio(xi);
  if (!(c.r1 > 0) || !std::isfinite(c.r1)) throw InvalidInput("--R1 " + format_number(c.r1) + ": must be finite and > 0");
  validate(c.material, "material");
  make_mode_ipr_solver(c.solver);  // throws on an unknown method
  if (c.selection) validate(*c.selection, c.n);
}

namespace {

std::vector<IprMapCell> compute_partial_ipr_map(const IprMapConfig& c, ProgressMeter* progress) {
  // ARPACK keeps its state in Fortran SAVE variables and SLEPc is MPI-collective: one thread.
  const bool threadable = c.partial_method == PartialMethod::lapack || c.partial_method == PartialMethod::bisect;
  const int threads = threadable ? resolve_threads(c.threads) : 1;
  const std::size_t n = c.n, realizations = c.realizations;
  PartialSpectrumConfig pc;
  pc.method = c.partial_method;
  std::vector<PartialSpectrum> slots(realizations);
  std::vector<Configuration> types(realizations);
  std::vector<IprMapCell> cells;
  for (double q : c.q_values) {
    parallel_realizations(realizations, threads, [&](std::size_t r, int) {
      types[r] = realization_configuration(c.disorder, q, n, c.seed, r);
    });
    for (double xi : c.xi_values) {
      parallel_realizations(
          realizations, threads,
          [&](std::size_t r, int) {
            const Chain chain = make_chain(radii_of(types[r], c.r1, xi), c.precompression, c.material);
            slots[r] = partial_spectrum(dynamical_matrix(chain), inverse_sqrt_mass(chain.inverse_mass), *c.selection, pc);
          },
          progress);
      IprMapCell cell{q, xi, {}, {}, {}, {}};
      for (std::size_t r = 0; r < realizations; ++r)  // fixed order: thread-count independent
        for (std::size_t j = 0; j < slots[r].size(); ++j) {
          cell.freq_khz.push_back(slots[r].freq_khz[j]);
          cell.ipr.push_back(slots[r].ipr[j]);
          cell.mode.push_back(slots[r].mode[j]);
          cell.realization.push_back(r);
        }
      cells.push_back(std::move(cell));
    }
  }
  return cells;
}

}  // namespace

std::vector<IprMapCell> compute_ipr_map(const IprMapConfig& c, ProgressMeter* progress) {
  validate(c);
  if (c.selection) return compute_partial_ipr_map(c, progress);
  const int threads = resolve_threads(c.threads);
  std::vector<std::unique_ptr<ModeIprSolver>> solvers;
  for (int t = 0; t < threads; ++t) solvers.push_back(make_mode_ipr_solver(c.solver));

  const std::size_t n = c.n, realizations = c.realizations;
  constexpr std::size_t batch = 4;  // chains per solve_batch call
  std::vector<double> omega2(realizations * n), ipr(realizations * n);  // slot r holds realization r
  std::vector<Configuration> types(realizations);
  std::vector<IprMapCell> cells;
  for (double q : c.q_values) {
    parallel_realizations(realizations, threads, [&](std::size_t r, int) {
      types[r] = realization_configuration(c.disorder, q, n, c.seed, r);
    });
    for (double xi : c.xi_values) {
      // Realizations go to the solver in fixed batches [b·B, b·B + B): a solver may overlap the
      // chains of a batch, and each chain's result is independent of the batch and the thread.
      const std::size_t batches = (realizations + batch - 1) / batch;
      parallel_realizations(batches, threads, [&](std::size_t b, int thread) {
        struct Work {
          std::vector<double> w2, p;
          SymTridiagonal d;
          std::vector<double> s;
        };
        thread_local std::vector<Work> work(batch);
        thread_local std::vector<ModeIprTask> tasks;
        tasks.clear();
        const std::size_t first = b * batch, last = std::min(realizations, first + batch);
        for (std::size_t r = first; r < last; ++r) {
          Work& w = work[r - first];
          const Chain chain = make_chain(radii_of(types[r], c.r1, xi), c.precompression, c.material);
          w.d = dynamical_matrix(chain);
          w.s = inverse_sqrt_mass(chain.inverse_mass);
          tasks.push_back({&w.d, &w.s, &w.w2, &w.p});
        }
        solvers[thread]->solve_batch(tasks);
        for (std::size_t r = first; r < last; ++r) {
          const Work& w = work[r - first];
          std::copy(w.w2.begin(), w.w2.end(), omega2.begin() + static_cast<long>(r * n));
          std::copy(w.p.begin(), w.p.end(), ipr.begin() + static_cast<long>(r * n));
        }
        if (progress) progress->advance(last - first);
      });
      IprMapCell cell{q, xi, std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), {}, {}};
      for (std::size_t r = 0; r < realizations; ++r)  // fixed order: thread-count independent
        for (std::size_t k = 0; k < n; ++k) {
          cell.freq_khz[k] += frequency_khz(omega2[r * n + k]);
          cell.ipr[k] += ipr[r * n + k];
        }
      for (std::size_t k = 0; k < n; ++k) {
        cell.freq_khz[k] /= static_cast<double>(realizations);
        cell.ipr[k] /= static_cast<double>(realizations);
      }
      cells.push_back(std::move(cell));
    }
  }
  return cells;
}

}  // namespace granular
