#include "granular/linear/spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "granular/detail/enum_names.hpp"
#include "granular/detail/memory_limit.hpp"
#include "granular/error.hpp"
#include "granular/linear/detail/lapack.hpp"
#include "granular/linear/detail/lapack_eigensolver.hpp"
#include "granular/linear/detail/mode_ipr_solver.hpp"
#include "granular/linear/detail/mode_vector.hpp"
#include "granular/linear/detail/partial_spectrum.hpp"
#include "granular/linear/detail/sturm_bisection.hpp"
#include "granular/linear/detail/twisted_ipr_solver.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/number_format.hpp"

namespace granular {

constexpr auto method_names = detail::enum_names<SpectrumMethod>("method", {{SpectrumMethod::lapack, "lapack"},
                                                                            {SpectrumMethod::fast, "fast"},
                                                                            {SpectrumMethod::bisect, "bisect"},
                                                                            {SpectrumMethod::arpack, "arpack"},
                                                                            {SpectrumMethod::slepc, "slepc"}});

std::string_view to_string(SpectrumMethod method) { return method_names.name_of(method); }

SpectrumMethod parse_spectrum_method(std::string_view name) { return method_names.parse(name); }

ModeSelection choose_modes(std::optional<double> near, std::optional<long> count,
                           std::optional<std::pair<double, double>> window_khz) {
  if (window_khz) {
    if (near || count) throw InvalidInput("window", " cannot be combined with `near`/`count`");
    return window(window_khz->first, window_khz->second);
  }
  if (!near && !count) return all_modes();
  if (!count) throw InvalidInput("near", " needs `count` (how many modes)");
  if (!near) throw InvalidInput("count", " needs `near` (the target frequency in kHz)");
  if (*count < 1) throw InvalidInput("count", " " + std::to_string(*count) + ": must be >= 1");
  return nearest(*near, *count);
}

void validate(const ModeSelection& s, std::size_t n) {
  switch (s.kind) {
    case ModeSelection::Kind::all: return;
    case ModeSelection::Kind::nearest:
      if (!std::isfinite(s.near_khz) || s.near_khz < 0)
        throw InvalidInput("near_khz", " " + format_number(s.near_khz) + ": must be a finite frequency >= 0 kHz");
      if (s.count < 1) throw InvalidInput("count", " " + std::to_string(s.count) + ": must be >= 1");
      if (static_cast<unsigned long>(s.count) > n)
        throw InvalidInput("count",
                           " " + std::to_string(s.count) + ": the chain has only N = " + std::to_string(n) + " modes");
      return;
    case ModeSelection::Kind::window:
      if (!std::isfinite(s.lo_khz) || !std::isfinite(s.hi_khz) || s.lo_khz < 0 || s.hi_khz < s.lo_khz)
        throw InvalidInput("window", " " + format_number(s.lo_khz) + ":" + format_number(s.hi_khz) +
                                         ": need finite 0 <= lo_khz <= hi_khz (kHz)");
      return;
  }
}

void validate(const SpectrumConfig& c, const ModeSelection& s) {
  const bool every = s.kind == ModeSelection::Kind::all;
  if (every && c.method != SpectrumMethod::lapack && c.method != SpectrumMethod::fast)
    throw InvalidInput("method", " " + std::string(to_string(c.method)) +
                                     ": computes selected modes; for every mode use lapack or fast");
  if (!every && c.method == SpectrumMethod::fast)
    throw InvalidInput("method", " fast: computes every mode; for nearest/window use lapack, bisect, arpack or slepc");
  if (c.method == SpectrumMethod::fast && c.vectors)
    throw InvalidInput("vectors", ": method fast computes no eigenvectors (use lapack)");
  if (c.lanes < 1 || c.lanes > 64) throw InvalidInput("lanes", " " + std::to_string(c.lanes) + ": must be in 1..64");
  if (!std::isfinite(c.tolerance) || c.tolerance < 0)
    throw InvalidInput("tolerance", " " + format_number(c.tolerance) + ": must be finite and >= 0");
  if (c.subspace < 0) throw InvalidInput("subspace", " " + std::to_string(c.subspace) + ": must be >= 0");
  // A setting of a solver that does not run is refused, never ignored (a partial solve of any
  // method falls back to bisect, so lanes act there; the fallback is never arpack or slepc).
  const SpectrumConfig defaults;
  if (every && c.lanes != defaults.lanes)
    throw InvalidInput("lanes", ": takes effect only with selected modes (`near` or `window`), not with every mode");
  const bool shift_invert = c.method == SpectrumMethod::arpack || c.method == SpectrumMethod::slepc;
  for (const auto& [name, given] : {std::pair{"tolerance", c.tolerance != defaults.tolerance},
                                    std::pair{"subspace", c.subspace != defaults.subspace}})
    if (given && !shift_invert)
      throw InvalidInput(name, ": takes effect only with `method` arpack or slepc, not `method` " +
                                   std::string(to_string(c.method)));
}

struct SpectrumSolver::Workspace {
  TwistedModeIpr fast;
  LapackEigensolver lapack;
  EigenDecomposition eig;
  explicit Workspace(LapackDriver driver) : lapack(driver) {}
};

SpectrumSolver::SpectrumSolver(const SpectrumConfig& config)
    : config_(config), work_(std::make_unique<Workspace>(config.driver)) {}
SpectrumSolver::~SpectrumSolver() = default;
SpectrumSolver::SpectrumSolver(SpectrumSolver&&) noexcept = default;
SpectrumSolver& SpectrumSolver::operator=(SpectrumSolver&&) noexcept = default;

namespace {

void check_matrix(const DynamicalMatrix& d) {
  const std::size_t n = d.size();
  if (n < 2) throw InvalidInput("N", " " + std::to_string(n) + ": a chain needs at least 2 beads");
  if (d.off_diagonal.size() != n - 1)
    throw InvalidInput("off_diagonal", ": must have N - 1 = " + std::to_string(n - 1) + " entries");
  if (d.inverse_sqrt_mass.size() != n)
    throw InvalidInput("inverse_sqrt_mass", ": must have N = " + std::to_string(n) + " entries");
  if (!d.all_finite()) throw InvalidInput("matrix", ": has NaN or infinite entries");
  for (double s : d.inverse_sqrt_mass)
    if (!std::isfinite(s) || !(s > 0)) throw InvalidInput("inverse_sqrt_mass", ": entries must be finite and > 0");
}

void number_modes(Spectrum& s) {
  s.mode.resize(s.omega2.size());
  s.freq_khz.resize(s.omega2.size());
  for (std::size_t k = 0; k < s.omega2.size(); ++k) {
    s.mode[k] = k + 1;
    s.freq_khz[k] = frequency_khz(s.omega2[k]);
  }
}

/// The largest eigenvalue of `d` to 1e-4 relative (plenty for a threshold), by bisection on node counts below the
/// Gershgorin bound: the scale of the cluster threshold for a partial result.
double largest_eigenvalue(const SymTridiagonal& d) {
  const std::size_t n = d.size();
  double hi = std::max(0.0, gershgorin_bounds(d, RowSum::left_to_right).second);
  double lo = 0;
  for (int it = 0; it < 60 && hi - lo > 1e-4 * hi; ++it) {
    const double mid = (lo + hi) / 2;
    (count_below_many(d, {mid})[0] < static_cast<long>(n) ? lo : hi) = mid;
  }
  return hi;
}

/// Cluster flags of a partial result: is there a second eigenvalue within the threshold of each?
/// First with the threshold of the Gershgorin bound, which is ≥ the largest eigenvalue: a mode
/// alone in that wider window is alone in the true one (counts are monotonic), and that settles
/// almost every mode in one sweep, without the ~14 sweeps of largest_eigenvalue.
/// A mode whose neighbours in the spectrum are both returned (consecutive mode numbers) and more
/// than twice the threshold away by value needs no count: the values are within ~ε‖T‖ of the true
/// eigenvalues (the node-count check's premise), 1e-6 of the threshold.
std::vector<std::uint8_t> partial_cluster_flags(const DynamicalMatrix& d, const std::vector<double>& omega2,
                                                const std::vector<std::size_t>& mode) {
  if (omega2.empty()) return {};
  auto neighbours = [&](double delta, const std::vector<std::size_t>& modes) {
    std::vector<double> shifts;
    for (std::size_t j : modes) {
      shifts.push_back(omega2[j] - delta);
      shifts.push_back(omega2[j] + delta);
    }
    const std::vector<long> below = count_below_many(d, shifts);
    std::vector<std::size_t> crowded;
    for (std::size_t q = 0; q < modes.size(); ++q)
      if (below[2 * q + 1] - below[2 * q] > 1) crowded.push_back(modes[q]);
    return crowded;
  };
  const double bound = std::max(0.0, gershgorin_bounds(d, RowSum::left_to_right).second);
  const double wide = cluster_relative_gap * bound;
  std::vector<std::size_t> unsettled;
  for (std::size_t j = 0; j < omega2.size(); ++j) {
    const bool inner = j > 0 && j + 1 < omega2.size() && mode[j - 1] + 1 == mode[j] && mode[j] + 1 == mode[j + 1];
    if (!inner || std::min(omega2[j] - omega2[j - 1], omega2[j + 1] - omega2[j]) <= 2 * wide) unsettled.push_back(j);
  }
  std::vector<std::size_t> crowded = unsettled.empty() ? unsettled : neighbours(wide, unsettled);
  if (!crowded.empty()) crowded = neighbours(cluster_relative_gap * largest_eigenvalue(d), crowded);
  std::vector<std::uint8_t> flags(omega2.size(), 0);
  for (std::size_t j : crowded) flags[j] = 1;
  return flags;
}

}  // namespace

std::vector<std::uint8_t> cluster_flags(std::span<const double> omega2) {
  const std::size_t n = omega2.size();
  std::vector<std::uint8_t> flags(n, 0);
  if (n < 2) return flags;
  const double delta = cluster_relative_gap * std::max(std::fabs(omega2.front()), std::fabs(omega2.back()));
  for (std::size_t k = 0; k + 1 < n; ++k)
    if (omega2[k + 1] - omega2[k] < delta) flags[k] = flags[k + 1] = 1;
  return flags;
}

std::uint64_t full_spectrum_bytes(std::size_t beads, const SpectrumConfig& config, const ModeSelection& selection) {
  if (selection.kind != ModeSelection::Kind::all || config.method != SpectrumMethod::lapack) return 0;
  const std::uint64_t n = beads, square = n * n;
  const std::uint64_t workspace = config.driver == LapackDriver::stevd ? square + 4 * n + 1 : 20 * n;
  return 8 * (square + workspace + (config.vectors ? square : 0) + 8 * n);
}

std::string full_spectrum_problem(std::size_t beads, const SpectrumConfig& config, const ModeSelection& selection) {
  const std::uint64_t bytes = full_spectrum_bytes(beads, config, selection);
  if (bytes == 0) return {};
  const std::uint64_t n = beads;
  std::string why;
  // Whatever driver is preferred, a failing one falls back to dstevd (lapack_eigensolver.hpp),
  // whose workspace must then fit: the limit is every vector-computing run's.
  if ((config.vectors || config.driver == LapackDriver::stevd) &&
      detail::stevd_workspace_overflows(static_cast<std::int64_t>(n)))
    why =
        "dstevd's workspace of N^2 + 4N + 1 doubles (every driver's fallback) exceeds LAPACK's 32-bit sizes "
        "(N <= 46338)";
  // The least of RAM, the cgroup's limit and ulimit -v: what this process may have.
  const detail::MemoryLimit memory = detail::memory_limit();
  if (why.empty() && memory.bytes > 0 && static_cast<double>(bytes) > memory.bytes)
    why = "more than the " + format_number(std::round(memory.bytes / 1e8) / 10) +
          " GB of memory this process may use (" + memory.source + ")";
  if (why.empty()) return {};
  return "every mode with eigenvectors (method lapack) needs " +
         format_number(std::round(static_cast<double>(bytes) / 1e8) / 10) + " GB: " + why;
}

Spectrum SpectrumSolver::solve(const DynamicalMatrix& d, const ModeSelection& selection) {
  check_matrix(d);
  validate(selection, d.size());
  validate(config_, selection);
  if (const std::string problem = full_spectrum_problem(d.size(), config_, selection); !problem.empty())
    throw InvalidInput("N", " " + std::to_string(d.size()) + ": " + problem +
                                "; what fits: method fast (every frequency and IPR, O(N) memory, no eigenvectors), "
                                "or selected modes (nearest/window) with method bisect");
  const std::size_t n = d.size();
  Spectrum out;
  out.beads = n;
  if (selection.kind == ModeSelection::Kind::all) {
    if (config_.method == SpectrumMethod::fast) {
      const TwistedIprInfo before = work_->fast.info();
      work_->fast.solve(d, d.inverse_sqrt_mass, out.omega2, out.ipr);
      const TwistedIprInfo& after = work_->fast.info();
      out.info.method = "fast";
      out.info.fallbacks = static_cast<int>(after.fallbacks - before.fallbacks);
      out.info.clusters = after.clusters - before.clusters;
    } else {
      EigenDecomposition& eig = work_->eig;
      work_->lapack.solve(d, true, eig);  // the IPRs need the vectors
      out.omega2.assign(eig.values.data(), eig.values.data() + n);
      out.ipr.resize(n);
      for (std::size_t k = 0; k < n; ++k)
        out.ipr[k] =
            displacement_ipr(eig.vectors.col(static_cast<Eigen::Index>(k)).data(), d.inverse_sqrt_mass.data(), n);
      if (config_.vectors) {
        out.vectors.assign(eig.vectors.data(), eig.vectors.data() + n * n);
        for (std::size_t k = 0; k < n; ++k) detail::normalize_mode(out.vectors.data() + k * n, n);
      }
      out.info.method = "lapack-" + std::string(to_string(eig.driver));
      out.info.fallbacks = eig.fallbacks;
    }
    out.info.candidates = static_cast<int>(n);
    number_modes(out);
    out.clustered = cluster_flags(out.omega2);
    return out;
  }
  out = partial_spectrum(d, d.inverse_sqrt_mass, selection, config_);
  for (double r : out.residual) out.info.max_residual = std::max(out.info.max_residual, r);
  out.clustered = partial_cluster_flags(d, out.omega2, out.mode);
  return out;
}

void SpectrumSolver::solve_all(std::span<const DynamicalMatrix* const> matrices, std::span<Spectrum> out) {
  if (out.size() != matrices.size()) throw InvalidInput("out", ": must have one Spectrum per matrix");
  if (config_.method != SpectrumMethod::fast) {
    for (std::size_t i = 0; i < matrices.size(); ++i) out[i] = solve(*matrices[i]);
    return;
  }
  std::vector<ModeIprTask> tasks(matrices.size());
  for (std::size_t i = 0; i < matrices.size(); ++i) {
    const DynamicalMatrix& d = *matrices[i];
    check_matrix(d);
    out[i] = Spectrum{};
    out[i].beads = d.size();
    tasks[i] = {&d, &d.inverse_sqrt_mass, &out[i].omega2, &out[i].ipr};
  }
  work_->fast.solve_batch(tasks);
  for (Spectrum& s : out) {  // clusters and fallbacks of a batch are not split per chain: left 0
    number_modes(s);
    s.clustered = cluster_flags(s.omega2);
    s.info.method = "fast";
    s.info.candidates = static_cast<int>(s.beads);
  }
}

Spectrum spectrum(const DynamicalMatrix& d, const ModeSelection& selection, const SpectrumConfig& config) {
  return SpectrumSolver(config).solve(d, selection);
}

}  // namespace granular
