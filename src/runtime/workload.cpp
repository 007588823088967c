#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::runtime {

std::uint64_t Workload::total_items() const {
  std::uint64_t total = 0;
  for (std::uint32_t s = 0; s < stage_count(); ++s) total += item_count(s);
  return total;
}

}  // namespace pbrfit::runtime
