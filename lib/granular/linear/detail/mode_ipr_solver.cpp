#include "granular/linear/detail/mode_ipr_solver.hpp"

#include <string>

#include "granular/error.hpp"
#include "granular/linear/detail/twisted_ipr_solver.hpp"
#include "granular/linear/mode_ipr.hpp"

namespace granular {

void LapackModeIpr::solve(const SymTridiagonal& d, const std::vector<double>& s, std::vector<double>& omega2,
                          std::vector<double>& ipr) {
  solver_.solve(d, true, eig_);
  const std::size_t n = d.size();
  omega2.assign(eig_.values.data(), eig_.values.data() + n);
  ipr.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    ipr[k] = displacement_ipr(eig_.vectors.col(static_cast<Eigen::Index>(k)).data(), s.data(), n);
}

std::unique_ptr<ModeIprSolver> make_mode_ipr_solver(std::string_view method) {
  if (method == "fast") return std::make_unique<TwistedModeIpr>();
  if (method == "lapack") return std::make_unique<LapackModeIpr>(LapackDriver::stevd);
  if (method.starts_with("lapack-")) return std::make_unique<LapackModeIpr>(parse_lapack_driver(method.substr(7)));
  throw InvalidInput("solver",
                     " '" + std::string(method) + "': expected fast, lapack or lapack-<stevr|stemr|stevd|steqr>");
}

}  // namespace granular
