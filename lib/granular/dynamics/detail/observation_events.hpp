#pragma once
// When a run stops to show its observers the chain, for spread() and spread_in_lanes() alike.
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "granular/dynamics/observer.hpp"

namespace granular::detail {

/// The union of the observers' schedules as (step, observer) in time order (at a shared step in
/// the order given), without duplicates, and always (T, observers.size()): a stop for no one at T.
std::vector<std::pair<std::uint64_t, std::size_t>> observation_events(std::span<Observer* const> observers,
                                                                      const RunPlan& plan);

}  // namespace granular::detail
