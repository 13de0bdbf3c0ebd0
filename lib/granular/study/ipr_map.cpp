#include "granular/study/ipr_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/model/chain.hpp"
#include "granular/number_format.hpp"

namespace granular {

ChainChoices ipr_map_chain_defaults() { return chain_choices(IprMapConfig{}.chain); }

void set_chain(IprMapConfig& c, const ChainChoices& beads) {
  set_study_draw(c.chain, beads);
  const ChainChoices kind = chain_kind_choices(beads);
  if (auto quasi = quasiperiodic(kind)) c.chain.source = *quasi;
  else if (auto distribution = bead_distribution(kind)) c.chain.source = *distribution;
  else return;
  c.q_values = c.xi_values = {std::numeric_limits<double>::quiet_NaN()};  // one cell
}

std::vector<double> paper_xi_values() { return parse_number_list("0.1:1:0.01", "xi"); }

namespace {
void read_map_xi(IprMapConfig& c, const std::string& text) { c.xi_values = parse_number_list(text, "xi", 0.01); }
std::string write_map_xi(const IprMapConfig& c) { return format_number_list(c.xi_values); }
void read_map_q(IprMapConfig& c, const std::string& text) { c.q_values = parse_number_list(text, "q", 0.1); }
std::string write_map_q(const IprMapConfig& c) { return format_number_list(c.q_values); }
}  // namespace

const ParameterTable<IprMapConfig>& ipr_map_parameters() {
  using C = IprMapConfig;
  static const ParameterTable<C> table{
      {"xi", {}, {read_map_xi, write_map_xi}, "size ratios R2/R1 in (0,1]: start:stop[:step] (step 0.01) or a,b,c"},
      {"q",
       {},
       {read_map_q, write_map_q},
       "probabilities of type 1 (or of dimer 11 / 12) in [0,1]: list or range (step 0.1)"},
      {"realizations", &C::realizations, "chains averaged per (q, xi)"},
      {"solver", &C::solver,
       "mode solver: fast (eigenvalues + one twisted factorization per mode, no eigenvector matrix; IPRs as "
       "LAPACK's to 1e-10 outside tight eigenvalue clusters) | lapack (= lapack-stevd) | lapack-stevr | "
       "lapack-stemr | lapack-stevd | lapack-steqr"},
      {"method", &C::method, "partial spectra: lapack (the default) | bisect | arpack (one thread)", false},
      {"bin_khz", &C::bin_khz,
       "average in frequency bins of this width [kHz] instead of by mode number: columns "
       "disorder,q,xi,freq_lo_khz,freq_hi_khz,modes,ipr (empty bins: modes 0, ipr nan); 0: by mode number"}};
  return table;
}

void set_solver(IprMapConfig& c) {
  const std::string& solver = c.solver;
  const std::optional<std::string> method = c.method.empty() ? std::nullopt : std::optional(c.method);
  const std::string expected = "': expected fast, lapack or lapack-<stevr|stemr|stevd|steqr>";
  if (solver != "fast" && solver != "lapack" && !solver.starts_with("lapack-"))
    throw InvalidInput("solver", " '" + solver + expected);
  c.spectrum.method = solver == "fast" ? SpectrumMethod::fast : SpectrumMethod::lapack;
  if (solver.starts_with("lapack-")) try {
      c.spectrum.driver = parse_lapack_driver(solver.substr(7));
    } catch (const InvalidInput&) {
      throw InvalidInput("solver", " '" + solver + expected);
    }
  if (c.selection.kind != ModeSelection::Kind::all) {  // near/count or window
    c.spectrum.method = parse_spectrum_method(method.value_or("lapack"));
    if (c.spectrum.method == SpectrumMethod::fast)
      throw InvalidInput("method", " fast: computes every mode; use lapack, bisect or arpack with `near`/`window`");
  } else if (method) {
    throw InvalidInput("method", ": only with `near`/`count` or `window` (the full map uses `solver`)");
  }
}

void validate(const IprMapConfig& c) {
  const ChainRecipe& chain = c.chain;
  if (chain.N < 2) throw InvalidInput("N", " " + std::to_string(chain.N) + ": a chain needs at least 2 beads");
  if (!(chain.F0 > 0) || !std::isfinite(chain.F0))
    throw InvalidInput("precompression", " " + format_number(chain.F0) + ": the linear spectrum needs a finite F0 > 0");
  if (c.realizations < 1) throw InvalidInput("realizations", " 0: must be >= 1");
  if (!chain.drawn()) throw InvalidInput("chain", ": an IPR map draws its chains; not a given chain");
  if (chain.typed()) {
    if (c.q_values.empty()) throw InvalidInput("q", ": no values");
    if (c.xi_values.empty()) throw InvalidInput("xi", ": no values");
    for (double q : c.q_values) validate_probability(q);
    for (double xi : c.xi_values) validate_size_ratio(xi);
  }
  validate(chain);
  validate(c.selection, chain.N);
  validate(c.spectrum, c.selection);
  // Every mode with eigenvectors (solver lapack) holds N × N doubles per thread: refused before any is allocated.
  if (const std::string problem = full_spectrum_problem(chain.N, c.spectrum, c.selection); !problem.empty())
    throw InvalidInput("N", " " + std::to_string(chain.N) + ": " + problem +
                                " (each thread solves one chain); what fits: the fast solver (every IPR in O(N) "
                                "memory) or selected "
                                "modes (`near` and `count`, or `window`)");
  if (!std::isfinite(c.bin_khz) || c.bin_khz < 0)
    throw InvalidInput("bin_khz",
                       " " + format_number(c.bin_khz) + ": must be finite and >= 0 (0 = average by mode number)");
  if (c.bin_khz > 0 && c.selection.kind != ModeSelection::Kind::all)
    throw InvalidInput("bin_khz", ": frequency bins average every mode; not with a nearest/window selection");
  if (c.spectrum.method == SpectrumMethod::slepc)
    throw InvalidInput("method", " slepc: the IPR map solves one chain per thread; use lapack, bisect or arpack");
}

namespace {

/// Realization r of the cell at ξ: from its bead types (drawn once for every ξ of a q), or drawn
/// from the bead distribution.
DynamicalMatrix matrix_of(const IprMapConfig& c, const Configuration& types, double xi, std::size_t r) {
  ChainRecipe cell = c.chain;
  if (auto* draw = cell.as<TwoTypeDraw>()) draw->xi = xi;
  return dynamical_matrix(cell.typed() ? cell.chain_of(types) : cell.chain(r));
}

/// The bead types of realization r at q (none with a bead distribution).
Configuration types_of(const IprMapConfig& c, double q, std::size_t r) {
  ChainRecipe cell = c.chain;
  if (auto* draw = cell.as<TwoTypeDraw>()) draw->q = q;
  return cell.types(r);
}

/// With a bead distribution or a quasiperiodic chain: one cell (q, ξ) = (NaN, NaN), whose types are not drawn.
IprMapConfig one_cell_if_distributed(const IprMapConfig& c) {
  IprMapConfig out = c;
  if (!c.chain.typed()) out.q_values = out.xi_values = {std::numeric_limits<double>::quiet_NaN()};
  return out;
}

/// The (q, ξ) grid in table order: every realization's bead types drawn once per q (in parallel),
/// then one `cell(q, xi, types)` per ξ; Cancelled between cells when run.cancelled says so.
template <class CellOf>
std::vector<IprMapCell> over_grid(const IprMapConfig& c, int threads, const RunOptions& run, CellOf&& cell) {
  std::vector<Configuration> types(c.realizations);
  std::vector<IprMapCell> cells;
  for (double q : c.q_values) {
    parallel_realizations(c.realizations, threads, [&](std::size_t r, int) { types[r] = types_of(c, q, r); });
    for (double xi : c.xi_values) {
      if (run.cancelled && run.cancelled()) throw Cancelled();
      cells.push_back(cell(q, xi, types));
    }
  }
  return cells;
}

std::vector<IprMapCell> compute_partial_ipr_map(const IprMapConfig& config, const RunOptions& run) {
  const IprMapConfig c = one_cell_if_distributed(config);
  // ARPACK keeps its state in Fortran SAVE variables: one thread.
  const int threads = c.spectrum.method == SpectrumMethod::arpack ? 1 : resolve_threads(run.threads);
  const std::size_t realizations = c.realizations;
  std::vector<Spectrum> slots(realizations);
  return over_grid(c, threads, run, [&](double q, double xi, const std::vector<Configuration>& types) {
    parallel_realizations(
        realizations, threads,
        [&](std::size_t r, int) { slots[r] = spectrum(matrix_of(c, types[r], xi, r), c.selection, c.spectrum); },
        run.progress);
    IprMapCell cell{q, xi, {}, {}, {}, {}, {}, {}, 0, 0};
    for (std::size_t r = 0; r < realizations; ++r)  // fixed order: thread-count independent
      for (std::size_t j = 0; j < slots[r].size(); ++j) {
        cell.freq_khz.push_back(slots[r].freq_khz[j]);
        cell.ipr.push_back(slots[r].ipr[j]);
        cell.mode.push_back(slots[r].mode[j]);
        cell.realization.push_back(r);
        cell.clustered_modes += slots[r].clustered[j];
      }
    cell.solved_modes = cell.ipr.size() * (c.selection.kind == ModeSelection::Kind::all ? realizations : 1);
    return cell;
  });
}

}  // namespace

std::vector<IprMapCell> compute_ipr_map(const IprMapConfig& config, const RunOptions& run) {
  validate(config);
  if (config.selection.kind != ModeSelection::Kind::all) return compute_partial_ipr_map(config, run);
  const IprMapConfig c = one_cell_if_distributed(config);
  const int threads = resolve_threads(run.threads);
  std::vector<SpectrumSolver> solvers;
  for (int t = 0; t < threads; ++t) solvers.emplace_back(c.spectrum);

  const std::size_t n = c.chain.N, realizations = c.realizations;
  // Chains per solve_all call: the fast solver runs a call's chains in vector lanes, which stay
  // fuller the more chains a call has; one call per thread and cell measured fastest
  // (docs/performance.md, "Chains in vector lanes"). Results do not depend on it.
  const std::size_t batch =
      std::clamp<std::size_t>((realizations + static_cast<std::size_t>(threads) - 1) / static_cast<std::size_t>(threads),
                              1, 64);
  std::vector<double> omega2(realizations * n), ipr(realizations * n);  // slot r holds realization r
  return over_grid(c, threads, run, [&](double q, double xi, const std::vector<Configuration>& types) {
    // Realizations go to the solver in fixed batches [b·B, b·B + B): a solver may overlap the
    // chains of a batch, and each chain's result is independent of the batch and the thread.
    const std::size_t batches = (realizations + batch - 1) / batch;
    parallel_realizations(batches, threads, [&](std::size_t b, int thread) {
      thread_local std::vector<DynamicalMatrix> matrices;
      thread_local std::vector<const DynamicalMatrix*> pointers;
      thread_local std::vector<Spectrum> results;
      if (matrices.size() < batch) {
        matrices.resize(batch);
        results.resize(batch);
      }
      const std::size_t first = b * batch, last = std::min(realizations, first + batch);
      pointers.clear();
      for (std::size_t r = first; r < last; ++r) {
        matrices[r - first] = matrix_of(c, types[r], xi, r);
        pointers.push_back(&matrices[r - first]);
      }
      solvers[thread].solve_all(pointers, std::span(results.data(), last - first));
      for (std::size_t r = first; r < last; ++r) {
        const Spectrum& s = results[r - first];
        std::copy(s.omega2.begin(), s.omega2.end(), omega2.begin() + static_cast<long>(r * n));
        std::copy(s.ipr.begin(), s.ipr.end(), ipr.begin() + static_cast<long>(r * n));
      }
      if (run.progress) run.progress->advance(last - first);
    });
    IprMapCell cell{q, xi, std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), {}, {}, {}, {}, 0, 0};
    for (std::size_t r = 0; r < realizations; ++r)
      for (std::uint8_t flag : cluster_flags(std::span(omega2).subspan(r * n, n))) cell.clustered_modes += flag;
    for (std::size_t r = 0; r < realizations; ++r)  // fixed order: thread-count independent
      for (std::size_t k = 0; k < n; ++k) {
        cell.freq_khz[k] += frequency_khz(omega2[r * n + k]);
        cell.ipr[k] += ipr[r * n + k];
      }
    for (std::size_t k = 0; k < n; ++k) {
      cell.freq_khz[k] /= static_cast<double>(realizations);
      cell.ipr[k] /= static_cast<double>(realizations);
    }
    if (c.bin_khz > 0) {  // same fixed order: realization-major, then mode
      double fmax = 0;
      for (double w2 : omega2) fmax = std::max(fmax, frequency_khz(w2));
      const auto bins = static_cast<std::size_t>(std::floor(fmax / c.bin_khz)) + 1;
      cell.bin_modes.assign(bins, 0);
      cell.bin_ipr.assign(bins, 0.0);
      for (std::size_t i = 0; i < realizations * n; ++i) {
        const auto b =
            std::min(bins - 1,
                     static_cast<std::size_t>(std::floor(std::max(0.0, frequency_khz(omega2[i])) / c.bin_khz)));
        ++cell.bin_modes[b];
        cell.bin_ipr[b] += ipr[i];
      }
      for (std::size_t b = 0; b < bins; ++b)
        cell.bin_ipr[b] = cell.bin_modes[b] > 0 ? cell.bin_ipr[b] / static_cast<double>(cell.bin_modes[b])
                                                : std::numeric_limits<double>::quiet_NaN();
    }
    cell.solved_modes = cell.ipr.size() * (c.selection.kind == ModeSelection::Kind::all ? realizations : 1);
    return cell;
  });
}

}  // namespace granular
