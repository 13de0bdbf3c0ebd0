// SLEPc shift-invert: Krylov–Schur on (T − σI)⁻¹ with the LU (MUMPS, partial pivoting, works
// for one rank or many) of a PETSc MPIAIJ matrix whose rows are spread over MPI_COMM_WORLD.
// The SLEPc component (libgranular_slepc.so; slepc_component.hpp): the only file that uses
// PETSc/SLEPc, compiled only when the build has SLEPc.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

#include "granular/error.hpp"
#include "granular/linear/detail/shift_invert_eigensolvers.hpp"
#include "granular/linear/detail/slepc_component.hpp"
#include "granular/parallel/mpi_context.hpp"

#include <mpi.h>
#include <slepceps.h>

namespace granular {

namespace {

bool started_by_us = false;

void finalize_slepc() {
  PetscBool up = PETSC_FALSE, done = PETSC_FALSE;
  SlepcInitialized(&up);
  PetscFinalized(&done);
  if (started_by_us && up && !done) SlepcFinalize();
}

void check(PetscErrorCode code, const char* what) {
  if (code != 0)
    throw NumericalError(std::string("SLEPc/PETSc: ") + what + " failed (error " + std::to_string(code) + ")");
}

void ensure_started() {
  PetscBool up = PETSC_FALSE;
  SlepcInitialized(&up);
  if (up) return;
  MpiContext::instance().require();  // MPI has one owner; PETSc then leaves MPI_Finalize to it
  check(SlepcInitialize(nullptr, nullptr, nullptr, nullptr), "SlepcInitialize");
  started_by_us = true;
  std::atexit(finalize_slepc);
}

/// Destroys PETSc objects on every exit path.
template <class T, PetscErrorCode (*Destroy)(T*)>
struct Owned {
  T p = nullptr;
  ~Owned() {
    if (p) Destroy(&p);
  }
};

}  // namespace

/// The eigenpairs of the assembled n × n matrix `a` nearest σ (the solve both matrix kinds share).
ShiftInvertResult solve_nearest(Mat a, PetscInt n, double sigma, const ShiftInvertConfig& config);

/// slepc_nearest() (shift_invert_eigensolvers.hpp), inside the component.
ShiftInvertResult slepc_shift_invert(const SymTridiagonal& t, double sigma, const ShiftInvertConfig& config) {
  const PetscInt n = static_cast<PetscInt>(t.size());
  require_nearest_count("SLEPc", t.size(), config.count);
  if (!std::isfinite(sigma)) throw InvalidInput("SLEPc", ": the shift must be finite");
  ensure_started();

  Owned<Mat, MatDestroy> a;
  check(MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n, n, 3, nullptr, 1, nullptr, &a.p), "MatCreateAIJ");
  PetscInt first = 0, last = 0;
  check(MatGetOwnershipRange(a.p, &first, &last), "MatGetOwnershipRange");
  for (PetscInt i = first; i < last; ++i) {
    PetscInt cols[3];
    PetscScalar vals[3];
    PetscInt k = 0;
    if (i > 0) {
      cols[k] = i - 1;
      vals[k++] = t.off_diagonal[i - 1];
    }
    cols[k] = i;
    vals[k++] = t.diagonal[i];
    if (i + 1 < n) {
      cols[k] = i + 1;
      vals[k++] = t.off_diagonal[i];
    }
    check(MatSetValues(a.p, 1, &i, k, cols, vals, INSERT_VALUES), "MatSetValues");
  }
  check(MatAssemblyBegin(a.p, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(a.p, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  return solve_nearest(a.p, n, sigma, config);
}

/// `m` as a PETSc MPIAIJ matrix over MPI_COMM_WORLD, each rank setting only the rows it owns.
void assemble_sparse(const SparseSymmetric& m, Mat* out) {
  const auto n = static_cast<PetscInt>(m.size());
  // Preallocated as the tridiagonal path is, by one count for every row: the longest row, inside
  // and outside this rank's diagonal block (every rank holds the whole matrix, so no message).
  PetscInt longest = 0;
  for (std::size_t i = 0; i < m.size(); ++i)
    longest = std::max(longest, static_cast<PetscInt>(m.row_start[i + 1] - m.row_start[i]));
  check(MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n, n, longest, nullptr, longest, nullptr, out),
        "MatCreateAIJ");
  PetscInt first = 0, last = 0;
  check(MatGetOwnershipRange(*out, &first, &last), "MatGetOwnershipRange");
  std::vector<PetscInt> cols;
  for (PetscInt i = first; i < last; ++i) {
    const std::size_t b = m.row_start[i], e = m.row_start[i + 1];
    cols.assign(m.column.begin() + static_cast<std::ptrdiff_t>(b), m.column.begin() + static_cast<std::ptrdiff_t>(e));
    check(MatSetValues(*out, 1, &i, static_cast<PetscInt>(e - b), cols.data(), m.value.data() + b, INSERT_VALUES),
          "MatSetValues");
  }
  check(MatAssemblyBegin(*out, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(*out, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

/// slepc_nearest() of a sparse matrix, inside the component: each rank sets its own rows.
ShiftInvertResult slepc_shift_invert_sparse(const SparseSymmetric& m, double sigma, const ShiftInvertConfig& config) {
  const PetscInt n = static_cast<PetscInt>(m.size());
  require_nearest_count("SLEPc", m.size(), config.count);
  if (!std::isfinite(sigma)) throw InvalidInput("SLEPc", ": the shift must be finite");
  ensure_started();

  Owned<Mat, MatDestroy> a;
  assemble_sparse(m, &a.p);
  return solve_nearest(a.p, n, sigma, config);
}

namespace {

/// Shift-and-invert with a direct factorization (`factor`: PCLU or PCCHOLESKY) by MUMPS, which
/// pivots (A − σI is indefinite) and runs on any number of ranks.
void use_mumps_shift_invert(EPS eps, PCType factor) {
  ST st;
  KSP ksp;
  PC pc;
  check(EPSGetST(eps, &st), "EPSGetST");
  check(STSetType(st, STSINVERT), "STSetType");
  check(STGetKSP(st, &ksp), "STGetKSP");
  check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PCSetType(pc, factor), "PCSetType");
  check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
}

/// Eigenpairs `which` of the solved `eps` (on matrix `a`) into `out`, in that order: the values,
/// and every vector gathered on every rank.
void gather_pairs(EPS eps, Mat a, const std::vector<PetscInt>& which, ShiftInvertResult& out) {
  PetscInt n = 0;
  check(MatGetSize(a, &n, nullptr), "MatGetSize");
  out.values.resize(which.size());
  out.vectors.resize(n, static_cast<Eigen::Index>(which.size()));
  Owned<Vec, VecDestroy> x, all;
  Owned<VecScatter, VecScatterDestroy> scatter;
  check(MatCreateVecs(a, &x.p, nullptr), "MatCreateVecs");
  check(VecScatterCreateToAll(x.p, &scatter.p, &all.p), "VecScatterCreateToAll");
  for (std::size_t j = 0; j < which.size(); ++j) {
    PetscScalar value = 0;
    check(EPSGetEigenpair(eps, which[j], &value, nullptr, x.p, nullptr), "EPSGetEigenpair");
    out.values[j] = value;
    check(VecScatterBegin(scatter.p, x.p, all.p, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
    check(VecScatterEnd(scatter.p, x.p, all.p, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
    const PetscScalar* p = nullptr;
    check(VecGetArrayRead(all.p, &p), "VecGetArrayRead");
    std::copy(p, p + n, out.vectors.col(static_cast<Eigen::Index>(j)).data());
    check(VecRestoreArrayRead(all.p, &p), "VecRestoreArrayRead");
  }
  if (!out.vectors.allFinite()) throw NumericalError("SLEPc returned non-finite eigenvectors");
}

}  // namespace

ShiftInvertResult solve_nearest(Mat a, PetscInt n, double sigma, const ShiftInvertConfig& config) {
  const PetscInt nev = config.count;
  Owned<EPS, EPSDestroy> eps;
  check(EPSCreate(PETSC_COMM_WORLD, &eps.p), "EPSCreate");
  check(EPSSetOperators(eps.p, a, nullptr), "EPSSetOperators");
  check(EPSSetProblemType(eps.p, EPS_HEP), "EPSSetProblemType");
  check(EPSSetType(eps.p, EPSKRYLOVSCHUR), "EPSSetType");
  const PetscInt ncv = config.subspace > 0 ? std::min<PetscInt>(n, std::max<PetscInt>(config.subspace, nev + 1))
                                           : std::min<PetscInt>(n, std::max<PetscInt>(2 * nev + 1, 20));
  check(EPSSetDimensions(eps.p, nev, ncv, PETSC_DEFAULT), "EPSSetDimensions");
  check(EPSSetTarget(eps.p, sigma), "EPSSetTarget");
  check(EPSSetWhichEigenpairs(eps.p, EPS_TARGET_MAGNITUDE), "EPSSetWhichEigenpairs");
  // 1e-14: tight enough for 1e-10 relative eigenvalues; machine precision would not converge.
  check(EPSSetTolerances(eps.p, config.tolerance > 0 ? config.tolerance : 1e-14, config.max_restarts),
        "EPSSetTolerances");
  // MUMPS's LDLᵀ (Bunch–Kaufman-like 2 × 2 pivots on the indefinite A − σI), the same on -np 1 and
  // -np P, with about half LU's factor storage (A − σI is symmetric).
  check(MatSetOption(a, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  use_mumps_shift_invert(eps.p, PCCHOLESKY);
  check(EPSSetFromOptions(eps.p), "EPSSetFromOptions");
  check(EPSSolve(eps.p), "EPSSolve");

  PetscInt nconv = 0, its = 0;
  check(EPSGetConverged(eps.p, &nconv), "EPSGetConverged");
  check(EPSGetIterationNumber(eps.p, &its), "EPSGetIterationNumber");
  if (nconv < nev)
    throw NumericalError("SLEPc: " + std::to_string(nconv) + " of " + std::to_string(nev) +
                         " eigenpairs converged in " + std::to_string(its) + " restarts");

  std::vector<double> values(nconv);
  for (PetscInt i = 0; i < nconv; ++i) {
    PetscScalar kr = 0, ki = 0;
    check(EPSGetEigenvalue(eps.p, i, &kr, &ki), "EPSGetEigenvalue");
    values[i] = kr;
  }
  // The nev converged pairs nearest σ, ascending.
  std::vector<PetscInt> order(nconv);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](PetscInt x, PetscInt y) { return std::fabs(values[x] - sigma) < std::fabs(values[y] - sigma); });
  order.resize(nev);
  std::sort(order.begin(), order.end(), [&](PetscInt x, PetscInt y) { return values[x] < values[y]; });

  ShiftInvertResult out;
  out.restarts = static_cast<int>(its);
  gather_pairs(eps.p, a, order, out);
  return out;
}

/// slepc_window() (shift_invert_eigensolvers.hpp), inside the component: Krylov–Schur's spectrum
/// slicing. It counts the eigenvalues below each shift from the inertia of the LDLᵀ of A − σI, so
/// the factorization is MUMPS's Cholesky (LDLᵀ for an indefinite matrix), with ICNTL(13) = 1: MUMPS
/// then factors the root node itself and can report the inertia on any number of ranks.
ShiftInvertResult slepc_window_sparse(const SparseSymmetric& m, double lo, double hi) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi)) throw InvalidInput("window", ": needs finite lo < hi");
  ensure_started();
  Owned<Mat, MatDestroy> a;
  assemble_sparse(m, &a.p);
  check(MatSetOption(a.p, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  Owned<EPS, EPSDestroy> eps;
  check(EPSCreate(PETSC_COMM_WORLD, &eps.p), "EPSCreate");
  check(EPSSetOperators(eps.p, a.p, nullptr), "EPSSetOperators");
  check(EPSSetProblemType(eps.p, EPS_HEP), "EPSSetProblemType");
  check(EPSSetType(eps.p, EPSKRYLOVSCHUR), "EPSSetType");
  check(EPSSetWhichEigenpairs(eps.p, EPS_ALL), "EPSSetWhichEigenpairs");
  check(EPSSetInterval(eps.p, lo, hi), "EPSSetInterval");
  check(EPSSetTolerances(eps.p, 1e-14, PETSC_DEFAULT), "EPSSetTolerances");
  use_mumps_shift_invert(eps.p, PCCHOLESKY);  // LDLᵀ: its inertia counts the eigenvalues below a shift
  // The slicing's inner solver takes its MUMPS options from the database (set, used, cleared).
  check(PetscOptionsSetValue(nullptr, "-st_mat_mumps_icntl_13", "1"), "PetscOptionsSetValue");
  check(EPSSetFromOptions(eps.p), "EPSSetFromOptions");
  const PetscErrorCode solved = EPSSolve(eps.p);
  PetscOptionsClearValue(nullptr, "-st_mat_mumps_icntl_13");
  check(solved, "EPSSolve (spectrum slicing)");

  PetscInt nconv = 0;
  check(EPSGetConverged(eps.p, &nconv), "EPSGetConverged");
  std::vector<PetscInt> every(static_cast<std::size_t>(nconv));
  std::iota(every.begin(), every.end(), 0);  // slicing returns them ascending
  ShiftInvertResult out;
  gather_pairs(eps.p, a.p, every, out);
  if (!std::is_sorted(out.values.begin(), out.values.end()))
    throw NumericalError("SLEPc spectrum slicing returned eigenvalues out of order");
  return out;
}

}  // namespace granular

const granular::detail::SlepcComponent* granular_slepc_component() {
  static const granular::detail::SlepcComponent component{&granular::slepc_shift_invert,
                                                          &granular::slepc_shift_invert_sparse,
                                                          &granular::slepc_window_sparse};
  return &component;
}
