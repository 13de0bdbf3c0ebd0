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

}  // namespace granular
