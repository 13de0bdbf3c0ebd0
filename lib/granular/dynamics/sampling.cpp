#include "granular/dynamics/sampling.hpp"

#include <algorithm>
#include <cmath>

#include "granular/detail/enum_names.hpp"
#include "granular/error.hpp"

namespace granular {

constexpr auto sampling_names =
    detail::enum_names<Sampling>("sampling", {{Sampling::logarithmic, "log"}, {Sampling::uniform, "uniform"}});

Sampling parse_sampling(const std::string& name) { return sampling_names.parse(name); }

std::string to_string(Sampling sampling) { return std::string(sampling_names.name_of(sampling)); }

std::vector<std::uint64_t> sample_steps(std::uint64_t total, std::size_t count, Sampling sampling) {
  std::vector<std::uint64_t> steps;
  if (sampling == Sampling::logarithmic) {
    const double span = std::log(static_cast<double>(total));
    for (std::size_t j = 0; j < count; ++j) {
      const double x = count == 1 ? 1.0 : static_cast<double>(j) / static_cast<double>(count - 1);
      steps.push_back(std::clamp<std::uint64_t>(static_cast<std::uint64_t>(std::llround(std::exp(x * span))), 1, total));
    }
    steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  } else {
    const std::uint64_t stride = std::max<std::uint64_t>(1, total / (count - 1));
    for (std::size_t j = 0; j < count && j * stride <= total; ++j) steps.push_back(j * stride);
  }
  return steps;
}

std::vector<std::uint64_t> with_dense_grid(std::vector<std::uint64_t> steps, const DenseGrid& grid, std::uint64_t total,
                                           double time_step) {
  if (grid.empty()) return steps;
  const auto at = [&](double t) { return static_cast<std::uint64_t>(std::llround(t / time_step)); };
  const std::uint64_t begin = at(grid.begin), end = std::min(at(grid.end), total);
  const std::uint64_t stride = std::max<std::uint64_t>(1, at(grid.step));
  std::erase_if(steps, [&](std::uint64_t s) { return s >= begin && s <= end; });
  for (std::uint64_t s = begin; s <= end; s += stride) steps.push_back(s);
  steps.push_back(end);
  std::sort(steps.begin(), steps.end());
  steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  return steps;
}

}  // namespace granular
