#include "granular/linear/spectrum_parameters.hpp"

#include <string>

namespace granular {
namespace {

using C = SpectrumConfig;
void read_method(C& c, const std::string& word) { c.method = parse_spectrum_method(word); }
std::string write_method(const C& c) { return std::string(to_string(c.method)); }
void read_driver(C& c, const std::string& word) { c.driver = parse_lapack_driver(word); }
std::string write_driver(const C& c) { return std::string(to_string(c.driver)); }

}  // namespace

const ParameterTable<SpectrumConfig>& spectrum_parameters() {
  using P = Parameter<C>;
  static const ParameterTable<C> table{
      P{"method",
        {},
        {read_method, write_method},
        "every mode: lapack (dstevd) | fast (eigenvalues + one twisted factorization per mode, no eigenvectors); "
        "`near`/`window`: lapack (dstemr by index) | bisect (Sturm bisection + inverse iteration, the fastest for "
        "long chains) | arpack | slepc (shift-invert; slepc runs on every mpirun rank)"}
          .as_word(),
      P{"driver",
        {},
        {read_driver, write_driver},
        "LAPACK driver of every mode by lapack: stevd | stevr | stemr | steqr (the others are its fallbacks)"}
          .as_word(),
      {"vectors", &C::vectors, "also return the unit eigenvectors w of D (not with fast)"},
      {"tolerance", &C::tolerance, "arpack/slepc: Ritz tolerance (0 = each method's tightest default)"},
      {"subspace", &C::subspace, "arpack/slepc: Krylov basis size (0 = max(2K + 1, 20))"},
      {"lanes", &C::lanes,
       "bisect: eigenvectors computed together, 1..64 (2 N x lanes doubles on a whole-chain solve; localized "
       "modes of long chains are solved on windows)"}};
  return table;
}

}  // namespace granular
