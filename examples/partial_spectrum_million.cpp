// The 10 modes nearest 15 kHz of an Anderson chain of 10⁶ beads, by Sturm bisection, without
// ever holding the full spectrum.
// Checked against an independent count: the transfer-matrix node count (Dean's method) below a
// frequency between two neighbouring modes found must equal the lower one's mode number, and the
// modes must be 10 consecutive numbers. Exits 1 if not.
#include <cstdio>
#include <vector>

#include <granular/granular.hpp>

int main() {
  const granular::ChainParameters p{.N = 1'000'000, .q = 0.5, .xi = 0.5, .seed = 1};
  const granular::Chain chain = granular::anderson(p);
  const granular::Spectrum near = granular::spectrum(granular::dynamical_matrix(chain), granular::nearest(15.0, 10),
                                                     {.method = granular::SpectrumMethod::bisect});
  std::vector<double> between;  // midpoints between neighbouring modes, and one above the last
  for (std::size_t j = 0; j + 1 < near.size(); ++j) between.push_back(0.5 * (near.freq_khz[j] + near.freq_khz[j + 1]));
  const std::vector<std::int64_t> below = granular::count_modes_below(*granular::chain_beads(chain), between);
  bool ok = near.size() == 10;
  for (std::size_t j = 0; j < near.size(); ++j) {
    std::printf("mode %7zu: %.9f kHz, IPR %.3e", near.mode[j], near.freq_khz[j], near.ipr[j]);
    if (j < between.size()) std::printf(", modes below %.9f kHz: %lld", between[j], static_cast<long long>(below[j]));
    std::printf("\n");
    ok = ok && (j == 0 || near.mode[j] == near.mode[j - 1] + 1);
    if (j < between.size()) ok = ok && below[j] == static_cast<std::int64_t>(near.mode[j]);
  }
  std::printf("%s: %s\n", near.info.method.c_str(), ok ? "mode numbers agree with the node counts" : "MISMATCH");
  return ok ? 0 : 1;
}
