#pragma once
// Which BLAS this process runs on. On Debian the library behind libblas.so.3 and liblapack.so.3 is
// chosen when the program starts (update-alternatives: the reference BLAS or OpenBLAS), not when
// it is built, so only the running process can say. It matters twice: the LAPACK, ARPACK and
// SLEPc paths sum in the BLAS's order (their results differ in the last bits between libraries)
// and run up to several times faster on OpenBLAS. Every run's JSON records it ("blas").
#include <string>

namespace granular {

/// The file the BLAS routine dgemv_ was loaded from, symbolic links resolved
/// ("/usr/lib/x86_64-linux-gnu/openblas-pthread/libblas.so.3"), preceded by OpenBLAS's own
/// description when it is OpenBLAS ("OpenBLAS 0.3.21 DYNAMIC_ARCH NO_AFFINITY Haswell
/// MAX_THREADS=64: …"); "unknown" when the symbol cannot be traced to a file.
std::string blas_library();

/// While alive, OpenBLAS runs on one thread (openblas_set_num_threads(1), the previous count
/// restored after; another BLAS is left as it is). For ensembles that run their realizations on
/// threads and ranks: OpenBLAS splits some sums (dsymv, in dsyevd's reduction) by its thread count,
/// which differs between a process and an MPI rank bound to one core, so without this a
/// realization's last bits would depend on where it ran. Not for concurrent use: make one around
/// the whole ensemble, on the thread that starts it.
class SerialBlas {
 public:
  SerialBlas();
  ~SerialBlas();
  SerialBlas(const SerialBlas&) = delete;
  SerialBlas& operator=(const SerialBlas&) = delete;

 private:
  int previous_ = 0;  ///< OpenBLAS's thread count before; 0: not OpenBLAS
};

}  // namespace granular
