#include "granular/study/solve_estimate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "granular/number_format.hpp"

namespace granular {

namespace {

/// The faster of two timed solves of every mode of `d`'s first `beads` beads [s].
double block_seconds(const DynamicalMatrix& d, std::size_t beads, const SpectrumConfig& config) {
  DynamicalMatrix block;  // the first beads, as walls at both ends would leave them
  const auto n = static_cast<std::ptrdiff_t>(beads);
  block.diagonal.assign(d.diagonal.begin(), d.diagonal.begin() + n);
  block.off_diagonal.assign(d.off_diagonal.begin(), d.off_diagonal.begin() + n - 1);
  block.inverse_sqrt_mass.assign(d.inverse_sqrt_mass.begin(), d.inverse_sqrt_mass.begin() + n);
  SpectrumSolver solver(config);
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 2; ++i) {  // the first call also sizes the workspaces
    const auto start = std::chrono::steady_clock::now();
    (void)solver.solve(block);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

}  // namespace

SolveEstimate estimate_every_mode_solve(const DynamicalMatrix& d, const SpectrumConfig& config,
                                        const ModeSelection& selection, std::size_t sample) {
  SolveEstimate e;
  e.beads = d.size();
  const bool every = selection.kind == ModeSelection::Kind::all;
  const bool timed = config.method == SpectrumMethod::lapack || config.method == SpectrumMethod::fast;
  if (!every || !timed || sample < 2 || d.size() < 8 * sample) return e;
  SpectrumConfig timing = config;
  timing.vectors = false;  // the IPRs need the vectors either way; returning them is a copy
  const double small = block_seconds(d, sample, timing);
  e.sample_beads = 2 * sample;
  e.sample_seconds = block_seconds(d, e.sample_beads, timing);
  e.power = std::clamp(small > 0 ? std::log2(e.sample_seconds / small) : 3.0, 2.0, 3.0);
  e.seconds = e.sample_seconds * std::pow(static_cast<double>(e.beads) / static_cast<double>(e.sample_beads), e.power);
  return e;
}

std::string describe(const SolveEstimate& e) {
  const auto rounded = [](double seconds) { return format_number(std::round(seconds * 1e3) / 1e3); };
  const std::string scale =
      e.seconds < 120 ? rounded(std::round(e.seconds)) + " s" : rounded(std::round(e.seconds / 6) / 10) + " min";
  return "every mode of " + std::to_string(e.beads) + " beads: about " + scale + " (" + std::to_string(e.sample_beads) +
         " beads took " + rounded(e.sample_seconds) + " s; time grows as N^" +
         format_number(std::round(e.power * 10) / 10) + " here); no further progress until it ends";
}

}  // namespace granular
