#pragma once
// ‖x‖₂ of a vector of doubles, summed left to right (std::inner_product is a strict left fold,
// unlike std::transform_reduce), so a norm written into a file or compared across runs is the
// same to the last bit on every build.
#include <cmath>
#include <numeric>
#include <span>

namespace granular::detail {

inline double euclidean_norm(std::span<const double> x) {
  return std::sqrt(std::inner_product(x.begin(), x.end(), x.begin(), 0.0));
}

}  // namespace granular::detail
