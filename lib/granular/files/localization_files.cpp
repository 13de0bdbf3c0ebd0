#include "granular/files/localization_files.hpp"

#include <nlohmann/json.hpp>
#include "granular/files/spectrum_file.hpp"
#include "granular/io/csv_writer.hpp"

namespace granular {

void write_localization_csv(std::ostream& out, const LocalizationScan& scan) {
  CsvWriter table(out, {"freq_khz", "lyapunov", "lyapunov_err", "loc_length", "idos", "dos", "resolved"});
  for (std::size_t k = 0; k < scan.frequency_khz.size(); ++k)
    table.row(scan.frequency_khz[k], scan.lyapunov[k], scan.lyapunov_error[k], scan.localization_length[k],
              scan.idos[k], scan.dos[k], static_cast<int>(scan.resolved[k]));
}

nlohmann::json describe_localization(const LocalizationScan& scan, const nlohmann::json& chain,
                                     const nlohmann::json& frequencies, int threads, const Material& material) {
  nlohmann::json meta;
  meta["chain"] = chain;
  meta["parameters"] = {{"frequencies_khz", frequencies},
                        {"frequency_count", scan.frequency_khz.size()},
                        {"segments", scan.segments},
                        {"threads", threads}};
  meta["columns"] = {
      {"freq_khz", "frequency f [kHz]"},
      {"lyapunov",
       "lambda = (1/N) ln ||(u_{N+1}, u_N)|| of the transfer-matrix recursion from u_0 = 0, u_1 = 1 [1/bead]"},
      {"lyapunov_err",
       "standard error of lambda: sqrt(sum_s (lambda_s - mean)^2 / (S (S-1))) over S consecutive "
       "segments of the chain (batch means; valid for segments much longer than loc_length)"},
      {"loc_length", "1/lambda [beads]; inf where lambda <= 0 (inside a band lambda is 0 up to O(1/N))"},
      {"idos", "eigenfrequencies of this finite chain (fixed walls) below f, per bead (exact node count)"},
      {"dos",
       "d idos/df by differences of neighbouring rows (central; one-sided at the ends) [1/(bead kHz)]; for a "
       "single frequency f, from the node counts at f -/+ 0.005 kHz (one-sided from f below 0.005 kHz)"},
      {"resolved", "1 where loc_length is a measurement, 0 where it is only a bound (see resolved_rule)"}};
  meta["resolved_rule"] = localization_resolved_rule();
  nlohmann::json edges = band_edges_of(chain, material);
  if (!edges.is_null()) meta["band_edges_khz"] = std::move(edges);
  return meta;
}

}  // namespace granular
