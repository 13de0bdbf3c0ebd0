#pragma once
// "Frequencies and IPRs of every mode" as one call, so the IPR map can use either the
// LAPACK eigenvectors or a faster method that never forms them. Instances keep their
// workspace: use one per thread.
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "granular/linear/detail/lapack_eigensolver.hpp"
#include "granular/linear/sym_tridiagonal.hpp"

namespace granular {

/// One chain of a batch: inputs and where its results go.
struct ModeIprTask {
  const SymTridiagonal* matrix = nullptr;
  const std::vector<double>* inverse_sqrt_mass = nullptr;
  std::vector<double>* omega2 = nullptr;
  std::vector<double>* ipr = nullptr;
};

class ModeIprSolver {
 public:
  virtual ~ModeIprSolver() = default;
  /// ω² ascending and the displacement IPR of each mode. `inverse_sqrt_mass` has m_n^{-1/2}.
  virtual void solve(const SymTridiagonal& d, const std::vector<double>& inverse_sqrt_mass, std::vector<double>& omega2,
                     std::vector<double>& ipr) = 0;
  /// Several independent chains; each result is exactly what solve() gives for that chain.
  /// The default solves them one by one; a solver may overlap their serial recurrences.
  virtual void solve_batch(std::span<const ModeIprTask> tasks) {
    for (const ModeIprTask& t : tasks) solve(*t.matrix, *t.inverse_sqrt_mass, *t.omega2, *t.ipr);
  }
};

/// Full eigen-decomposition by a LAPACK driver, then Σv⁴/(Σv²)² per eigenvector.
class LapackModeIpr final : public ModeIprSolver {
 public:
  explicit LapackModeIpr(LapackDriver driver = LapackDriver::stevd) : solver_(driver) {}
  void solve(const SymTridiagonal& d, const std::vector<double>& inverse_sqrt_mass, std::vector<double>& omega2,
             std::vector<double>& ipr) override;

 private:
  LapackEigensolver solver_;
  EigenDecomposition eig_;
};

/// "fast" (TwistedModeIpr, twisted_ipr_solver.hpp), "lapack" (LapackModeIpr with dstevd) or
/// "lapack-<driver>"; other methods register here too.
std::unique_ptr<ModeIprSolver> make_mode_ipr_solver(std::string_view method);

}  // namespace granular
