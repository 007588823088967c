#pragma once
// The results of finished work items, keyed by (stage, item). Held by the coordinator; it is exactly
// what a checkpoint stores, and all a job kind may look at when it builds a later stage.
#include <cstdint>
#include <map>
#include <utility>

#include "pbrfit/core/bytes.hpp"

namespace pbrfit {

struct WorkItemId {
  std::uint32_t stage = 0;
  std::uint64_t item = 0;
  auto operator<=>(const WorkItemId&) const = default;
};

// Ordered by (stage, item), so iteration order never depends on arrival order.
using ItemResults = std::map<WorkItemId, Bytes>;

}  // namespace pbrfit
