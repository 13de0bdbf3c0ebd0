// The C++ side of tests/benchmarks/python_vs_cpp.sh: a loop of small spectrum calls, each a new
// chain (realization i of seed 1) → its dynamical matrix → every mode by LAPACK, exactly what
//   for i in range(count): granular.spectrum(granular.anderson(N=N, realization=i))
// does from Python. Prints the median over `repeats` of the whole loop's wall time [s].
// Usage: spectrum_loop N COUNT REPEATS
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "granular/granular.hpp"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: spectrum_loop N COUNT REPEATS\n");
    return 2;
  }
  const auto n = static_cast<std::size_t>(std::atol(argv[1]));
  const long count = std::atol(argv[2]), repeats = std::atol(argv[3]);
  std::vector<double> seconds;
  double checksum = 0;  // keeps the work observable
  for (long r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < count; ++i) {
      const granular::Chain chain = granular::anderson({.N = n, .realization = static_cast<std::uint64_t>(i)});
      const granular::Spectrum s = granular::spectrum(granular::dynamical_matrix(chain));
      checksum += s.ipr[0];
    }
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  std::printf("%.6f %.17g\n", seconds[seconds.size() / 2], checksum);
  return 0;
}
