#pragma once
// What the runtime needs of a job kind. Work is a sequence of stages (one for a LUT; one per level of a
// hierarchical sweep; one per migration epoch of island GP); the items of a stage are independent and
// are handed out dynamically to whichever rank is free.
//
// Contract (it is what makes results independent of rank count, arrival order and interruptions):
//  - compute() is a pure function of (job text, stage, item, stage context); it may run on any rank,
//    concurrently with the other const members on rank 0;
//  - stage_context() depends only on the results of earlier stages;
//  - blocks() places a result at positions fixed by its item id.
#include <cstdint>
#include <string>
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/core/item_results.hpp"
#include "pbrfit/store/result_layout.hpp"

namespace pbrfit::runtime {

class Workload {
 public:
  virtual ~Workload() = default;

  virtual store::ResultLayout layout() const = 0;
  virtual std::uint32_t stage_count() const { return 1; }
  virtual std::uint64_t item_count(std::uint32_t stage) const = 0;
  // Shared input of a stage, built on rank 0 and sent to every rank before the stage's items.
  virtual Bytes stage_context(std::uint32_t /*stage*/, const ItemResults& /*finished*/) const { return {}; }
  virtual Bytes compute(std::uint32_t stage, std::uint64_t item, const Bytes& context) const = 0;
  virtual std::vector<store::Block> blocks(WorkItemId id, const Bytes& result) const = 0;
  // One line for progress logs and `pbrfit status`, from the results so far.
  virtual std::string headline(const ItemResults& finished) const = 0;

  std::uint64_t total_items() const;
};

}  // namespace pbrfit::runtime
