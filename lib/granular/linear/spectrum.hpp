#pragma once
// The linear spectrum of a chain in one call (docs/physics.md, "The linear spectrum"): every mode, the K modes nearest a
// frequency, or every mode in a frequency window — frequencies, displacement IPRs and, if asked,
// the eigenvectors — by any of the solvers, with a separate report of what ran.
//
//   auto d    = granular::dynamical_matrix(chain);
//   auto all  = granular::spectrum(d);                                     // every mode
//   auto near = granular::spectrum(d, granular::nearest(15.0, 20),         // 20 modes nearest 15 kHz
//                                  {.method = granular::SpectrumMethod::bisect});
//
// Modes are numbered 1…N by increasing frequency in the full spectrum; a partial result carries
// those numbers. "Nearest" means nearest in frequency |f − f0| (ties: the lower mode first).
// Which method for which job:
//   every mode:   lapack (default; LAPACK driver `driver`, eigenvectors available) or fast
//                 (eigenvalues + one twisted factorization per mode: ~5× faster, no eigenvectors;
//                 the IPR map's default);
//   nearest/window: lapack (dstemr by index), bisect (many-shift Sturm bisection + inverse
//                 iteration: the fastest for long chains; a localized mode of a chain of ≥ 8192
//                 beads is solved on a window of a few thousand rows, other modes in the whole
//                 chain with 2 N doubles per lane), arpack or slepc
//                 (shift-invert Krylov; slepc is collective over MPI ranks: under mpirun every rank
//                 calls it with the same matrix and gets the same result).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "granular/linear/dynamical_matrix.hpp"

namespace granular {

/// Which modes.
struct ModeSelection {
  enum class Kind { all, nearest, window } kind = Kind::all;
  double near_khz = 0;  ///< nearest: target frequency [kHz], finite, ≥ 0
  long count = 0;       ///< nearest: how many modes, 1 ≤ count ≤ N
  double lo_khz = 0;    ///< window: [lo_khz, hi_khz] in kHz, 0 ≤ lo ≤ hi, both ends included
  double hi_khz = 0;
};
/// Every mode.
inline ModeSelection all_modes() { return {}; }
/// The `count` modes nearest `khz` [kHz] in frequency.
inline ModeSelection nearest(double khz, long count) { return {ModeSelection::Kind::nearest, khz, count, 0, 0}; }
/// Every mode with lo_khz ≤ f ≤ hi_khz [kHz] (may be empty).
inline ModeSelection window(double lo_khz, double hi_khz) {
  return {ModeSelection::Kind::window, 0, 0, lo_khz, hi_khz};
}

/// The modes a front end's choices select, the one rule of the tools and Python: the `count` modes
/// nearest `near` [kHz] (both given), every mode in the `window` (lo, hi) [kHz], or every mode when
/// none is given. Throws InvalidInput naming `near`, `count` or `window` when the window comes with
/// `near`/`count`, one of `near` and `count` comes without the other, or count < 1; the chain's own
/// limits are validate's.
ModeSelection choose_modes(std::optional<double> near, std::optional<long> count,
                           std::optional<std::pair<double, double>> window);

/// Throws InvalidInput (naming near_khz, count or window) unless the selection makes sense for an
/// N-bead chain: count ≤ 0 or > N is an error; near_khz above the spectrum is not (it selects the
/// top modes); a window without modes is valid and gives an empty result.
void validate(const ModeSelection& selection, std::size_t beads);

enum class SpectrumMethod { lapack, fast, bisect, arpack, slepc };
std::string_view to_string(SpectrumMethod method);
/// "lapack" | "fast" | "bisect" | "arpack" | "slepc"; throws InvalidInput naming `method`.
SpectrumMethod parse_spectrum_method(std::string_view name);

/// LAPACK driver of the full spectrum (method lapack, every mode).
enum class LapackDriver {
  stevr,  ///< MRRR (dstemr underneath, with a dstebz+dstein fallback of its own)
  stemr,  ///< MRRR called directly; fails (info 22) on some chains with tight clusters
  stevd,  ///< divide and conquer: the default, fastest here at n ~ 100 and orthogonal to O(nε)
  steqr,  ///< implicit QL/QR, the slow and sure one
};
std::string_view to_string(LapackDriver driver);
/// "stevr" | "stemr" | "stevd" | "steqr"; throws InvalidInput naming `driver`.
LapackDriver parse_lapack_driver(std::string_view name);

struct SpectrumConfig {
  SpectrumMethod method = SpectrumMethod::lapack;
  LapackDriver driver = LapackDriver::stevd;  ///< lapack, every mode: preferred driver (others are fallbacks)
  bool vectors = false;                       ///< also return the eigenvectors (not with fast)
  double tolerance = 0;                       ///< arpack/slepc: Ritz tolerance; 0 = each method's tightest default
  int subspace = 0;                           ///< arpack/slepc: Krylov basis size; 0 = max(2K + 1, 20)
  std::size_t lanes = 8;  ///< bisect: eigenvectors computed together in the whole chain, 1…64 (memory 2 N × lanes
                          ///< doubles; localized modes of long chains are solved on windows instead)
};

/// Throws InvalidInput (naming the field) on a method that cannot do the selection, fast with
/// vectors, lanes outside 1…64, or a setting that would take no effect: lanes with every mode,
/// tolerance or subspace with a method other than arpack and slepc.
void validate(const SpectrumConfig& config, const ModeSelection& selection);

/// Memory [bytes] of every mode by method lapack for an N-bead chain: the N × N eigenvectors, the
/// driver's workspace (dstevd: N² + 4N + 1 doubles) and a second N × N copy when vectors are
/// returned; 0 for any other method or selection (they need O(N) per mode).
std::uint64_t full_spectrum_bytes(std::size_t beads, const SpectrumConfig& config, const ModeSelection& selection);
/// Why every mode by method lapack cannot run for N beads on this machine ("" when it can): dstevd's
/// workspace past LAPACK's 32-bit sizes (N > 46338), or full_spectrum_bytes above the physical
/// memory. Checked before anything is allocated, so a refusal costs nothing.
std::string full_spectrum_problem(std::size_t beads, const SpectrumConfig& config, const ModeSelection& selection);

/// What the solver did: for reports and for reproducing a result.
struct SpectrumInfo {
  std::string method;        ///< what ran: "fast", "lapack-stevd", "lapack-stemr", "bisect", "arpack", "slepc"
  int fallbacks = 0;         ///< drivers that failed before the one that ran (lapack), chains that fell back (fast),
                             ///< 1 when a nearest/window result failed its node-count check and bisect recomputed it
                             ///< (method then reads e.g. "arpack→bisect"); a failing bisect throws NumericalError
  int restarts = 0;          ///< arpack/slepc outer iterations
  int candidates = 0;        ///< eigenpairs computed to select from (≥ the modes returned)
  double max_residual = 0;   ///< max ‖D w − ω² w‖ / max|D_ij| over returned unit vectors (0 when not computed)
  std::size_t clusters = 0;  ///< fast: near-degenerate clusters (relative gap < 1e-10) given their most localized basis
};

/// Near-degenerate clusters. A mode whose ω² lies within cluster_relative_gap · max ω² of another
/// mode's is *clustered*: its eigenvector is fixed by the double-precision matrix only to an angle
/// ~ε‖D‖/gap ≳ 1e-6, so inside the cluster any orthonormal basis is as valid and its IPR depends on
/// the basis a solver happens to choose (the fast solver picks the most localized one, LAPACK
/// another). The same threshold as the solvers' own cluster handling.
inline constexpr double cluster_relative_gap = 1e-10;

/// flags[k] = 1 when mode k of the ascending eigenvalues `omega2` (a whole spectrum) has a
/// neighbour closer than cluster_relative_gap · max ω², else 0.
std::vector<std::uint8_t> cluster_flags(std::span<const double> omega2);

/// The selected modes, by increasing frequency.
struct Spectrum {
  std::vector<std::size_t> mode;  ///< mode numbers 1…N in the full spectrum
  std::vector<double> omega2;     ///< eigenvalues ω² of D [1/s²]
  std::vector<double> freq_khz;   ///< f = ω/2π [kHz]
  std::vector<double> ipr;        ///< displacement IPR Σv⁴/(Σv²)², v = M^{-1/2} w, in (0, 1]
  std::vector<double> residual;   ///< per mode ‖D w − ω² w‖ / max|D_ij| (partial methods; empty for every-mode)
  /// Per mode: 1 when it belongs to a near-degenerate cluster (another eigenvalue of the whole
  /// spectrum within cluster_relative_gap · max ω², found by node counts for a partial result), so
  /// that its IPR depends on the basis chosen inside the cluster; else 0. Every method fills it.
  std::vector<std::uint8_t> clustered;
  /// N × size() unit eigenvectors w of D, column-major (mode j at [j·N, (j+1)·N)), sign fixed by a
  /// positive largest entry; empty unless SpectrumConfig::vectors. Displacements: v = w ⊙ m^{-1/2}.
  std::vector<double> vectors;
  std::size_t beads = 0;  ///< N
  SpectrumInfo info;

  std::size_t size() const { return omega2.size(); }
  /// Eigenvector w of mode j (0-based position in this result); needs vectors.
  std::span<const double> vector(std::size_t j) const { return {vectors.data() + j * beads, beads}; }
};

/// Keeps the solvers' workspaces between calls: use one per thread for loops over many chains.
class SpectrumSolver {
 public:
  explicit SpectrumSolver(const SpectrumConfig& config = {});
  ~SpectrumSolver();
  SpectrumSolver(SpectrumSolver&&) noexcept;
  SpectrumSolver& operator=(SpectrumSolver&&) noexcept;

  /// The selected modes of `d`. Throws InvalidInput (bad selection/config, non-finite matrix, a full
  /// spectrum that does not fit: full_spectrum_problem, naming `N` and the methods that fit) or
  /// NumericalError (every solver failed).
  Spectrum solve(const DynamicalMatrix& d, const ModeSelection& selection = all_modes());
  /// Every mode of several chains; out[i] is exactly what solve(*matrices[i]) gives (fast
  /// overlaps the chains' serial recurrences, up to 4 at a time), except that info.clusters and
  /// info.fallbacks stay 0.
  void solve_all(std::span<const DynamicalMatrix* const> matrices, std::span<Spectrum> out);
  const SpectrumConfig& config() const { return config_; }

 private:
  struct Workspace;
  SpectrumConfig config_;
  std::unique_ptr<Workspace> work_;
};

/// One call: SpectrumSolver(config).solve(d, selection).
Spectrum spectrum(const DynamicalMatrix& d, const ModeSelection& selection = all_modes(),
                  const SpectrumConfig& config = {});

}  // namespace granular
