#include "granular/study/localization_scan.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "granular/error.hpp"
#include "granular/linear/density_of_states.hpp"
#include "granular/linear/transfer_matrix.hpp"
#include "granular/number_format.hpp"

namespace granular {

bool localization_resolved(double lyapunov, std::size_t beads, std::size_t segments) {
  if (!(lyapunov > 0) || beads < 2 || segments == 0) return false;
  const double n = static_cast<double>(beads);
  const double floor = std::log(n) / n;
  const double segment_length = n / static_cast<double>(segments);
  return lyapunov >= kResolvedFloorFactor * floor && segment_length * lyapunov >= kResolvedSegmentFactor;
}

const char* localization_resolved_rule() {
  return "resolved = 1 iff lambda >= 10 ln(N)/N (at f = 0 the recursion grows linearly and lambda = ln(N)/N: "
         "the finite-size floor) and every segment is at least 10 loc_length long (N/segments >= 10/lambda, "
         "so the segments behind lyapunov_err are independent); otherwise loc_length is only a lower bound of "
         "order N or N/segments and is not a measurement";
}

void validate(const LocalizationScanConfig& config) {
  const auto& f = config.frequency_khz;
  if (f.empty()) throw InvalidInput("f", ": the list of frequencies is empty");
  for (std::size_t k = 0; k < f.size(); ++k) {
    if (!std::isfinite(f[k]) || f[k] < 0)
      throw InvalidInput("f", ": " + format_number(f[k]) + " kHz (value " + std::to_string(k + 1) +
                                  "): frequencies must be finite and >= 0");
    if (k > 0 && !(f[k] > f[k - 1]))
      throw InvalidInput("f", ": frequencies must increase (the DOS differences neighbours): " + format_number(f[k]) +
                                  " kHz after " + format_number(f[k - 1]));
  }
  if (config.segments < 2 || config.segments > 1000000)
    throw InvalidInput("segments", " " + std::to_string(config.segments) + ": must be in [2, 1e6]");
}

LocalizationScan localization_scan(const BeadSource& chain, const LocalizationScanConfig& config, const RunOptions& run) {
  validate(config);
  if (run.threads < 0) throw InvalidInput("threads", " " + std::to_string(run.threads) + ": must be >= 0");
  TransferMatrixConfig tm;
  tm.segments = config.segments;
  tm.threads = run.threads;
  if (run.progress || run.cancelled)
    tm.progress = [&run](std::size_t steps) {
      if (run.cancelled && run.cancelled()) throw Cancelled();  // every worker stops at its next piece
      if (run.progress) run.progress->advance(steps);
    };
  TransferMatrixScan scan = transfer_matrix_scan(chain, config.frequency_khz, tm);

  LocalizationScan out;
  out.beads = scan.beads;
  out.segments = scan.segments;
  out.idos = integrated_density_of_states(scan.modes_below, scan.beads);
  if (scan.frequency_khz.size() == 1) {
    // Nothing to difference: count modes just below and above f instead (the counts are exact, so
    // this is the same difference quotient a list with that step would give).
    const double f = scan.frequency_khz[0], half = kSingleFrequencyDosStepKhz / 2;
    const std::vector<double> around =
        f >= half ? std::vector<double>{f - half, f + half} : std::vector<double>{f, f + half};
    const std::vector<double> idos =
        integrated_density_of_states(count_modes_below(chain, around, run.threads), scan.beads);
    out.dos = {(idos[1] - idos[0]) / (around[1] - around[0])};
  } else {
    out.dos = density_of_states(scan.frequency_khz, out.idos);
  }
  out.localization_length.resize(scan.lyapunov.size());
  out.resolved.resize(scan.lyapunov.size());
  for (std::size_t k = 0; k < scan.lyapunov.size(); ++k) {
    out.localization_length[k] = scan.lyapunov[k] > 0 ? 1.0 / scan.lyapunov[k] : std::numeric_limits<double>::infinity();
    out.resolved[k] = localization_resolved(scan.lyapunov[k], scan.beads, scan.segments) ? 1 : 0;
  }
  out.frequency_khz = std::move(scan.frequency_khz);
  out.lyapunov = std::move(scan.lyapunov);
  out.lyapunov_error = std::move(scan.lyapunov_error);
  out.modes_below = std::move(scan.modes_below);
  return out;
}

}  // namespace granular
