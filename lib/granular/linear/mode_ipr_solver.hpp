#pragma once
// "Frequencies and IPRs of every mode" as one call, so the IPR map can use either the
// LAPACK eigenvectors or a faster method that never forms them. Instances keep their
// workspace: use one per thread.
#include <memory>
#include <string_view>
#include <vector>

#include "granular/linear/lapack_eigensolver.hpp"
#include "granular/linear/sym_tridiagonal.hpp"

namespace granular {

class ModeIprSolver {
 public:
  virtual ~ModeIprSolver() = default;
  /// ω² ascending and the displacement IPR of each mode. `inverse_sqrt_mass` has m_n^{-1/2}.
  virtual void solve(const SymTridiagonal& d, const std::vector<double>& inverse_sqrt_mass,
                     std::vector<double>& omega2, std::vector<double>& ipr) = 0;
};

/// Full eigen-decomposition by a LAPACK driver, then Σv⁴/(Σv²)² per eigenvector.
class LapackModeIpr final : public ModeIprSolver {
 public:
  explicit LapackModeIpr(LapackDriver driver = LapackDriver::stevr) : solver_(driver) {}
  void solve(const SymTridiagonal& d, const std::vector<double>& inverse_sqrt_mass, std::vector<double>& omega2,
             std::vector<double>& ipr) override;

 private:
  LapackEigensolver solver_;
  EigenDecomposition eig_;
};

/// "fast" (TwistedModeIpr, twisted_ipr_solver.hpp), "lapack" (LapackModeIpr with dstevr) or
/// "lapack-<driver>"; other methods register here too.
std::unique_ptr<ModeIprSolver> make_mode_ipr_solver(std::string_view method);

}  // namespace granular
