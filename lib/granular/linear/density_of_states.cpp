#include "granular/linear/density_of_states.hpp"

#include <limits>
#include <string>

#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {

std::vector<std::int64_t> count_modes_below(const BeadSource& chain, const std::vector<double>& frequency_khz,
                                            int threads) {
  TransferMatrixConfig config;
  config.threads = threads;
  return transfer_matrix_scan(chain, frequency_khz, config).modes_below;
}

std::vector<double> integrated_density_of_states(const std::vector<std::int64_t>& modes_below, std::size_t beads) {
  if (beads == 0) throw InvalidInput("beads", " 0: the chain is empty");
  std::vector<double> idos(modes_below.size());
  for (std::size_t k = 0; k < idos.size(); ++k)
    idos[k] = static_cast<double>(modes_below[k]) / static_cast<double>(beads);
  return idos;
}

std::vector<double> density_of_states(const std::vector<double>& f, const std::vector<double>& idos) {
  if (f.size() != idos.size())
    throw InvalidInput("frequencies",
                       ": " + std::to_string(f.size()) + " values for " + std::to_string(idos.size()) + " IDOS values");
  for (std::size_t k = 1; k < f.size(); ++k)
    if (!(f[k] > f[k - 1]))
      throw InvalidInput("frequencies", ": must increase strictly to difference the IDOS (value " +
                                            std::to_string(k + 1) + " = " + format_number(f[k]) + " kHz after " +
                                            format_number(f[k - 1]) + ")");
  const std::size_t n = f.size();
  std::vector<double> dos(n, std::numeric_limits<double>::quiet_NaN());
  if (n < 2) return dos;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t lo = k == 0 ? 0 : k - 1, hi = k + 1 == n ? k : k + 1;
    dos[k] = (idos[hi] - idos[lo]) / (f[hi] - f[lo]);
  }
  return dos;
}

}  // namespace granular
