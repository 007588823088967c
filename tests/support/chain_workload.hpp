#pragma once
// A synthetic multi-stage workload for testing and benchmarking the runtime: stage s of N items, where
// every item reads the context of its stage (built from ALL results of stage s-1) and its own input
// (its own and its ring neighbour's results of stage s-1), draws random numbers, costs unevenly, and
// writes a fixed table, a growing table of records and a random-number table. compute() refuses a
// context built from fewer than N results, so a stage boundary that starts too early fails the job.
#include <csignal>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::testing {

struct ChainSettings {
  std::uint32_t stages = 3;
  std::uint64_t items = 16;
  std::size_t result_bytes = 16;    // at least 16: value and random number, the rest is filler state
  std::uint32_t spin_microseconds = 0;  // item i costs spin * (i * 7 % 5) microseconds
  bool log_rows = true;             // items append (item % 3) records to the growing table
  // Fault injection on rank 0: raise `signal` when `signal_stage` starts (signal_after = 0) or once
  // signal_after of its results have been collected; fail item `fail_item` of stage `fail_stage`.
  int signal = 0;
  std::uint32_t signal_stage = std::numeric_limits<std::uint32_t>::max();
  std::uint64_t signal_after = 0;
  std::uint32_t fail_stage = std::numeric_limits<std::uint32_t>::max();
  std::uint64_t fail_item = 0;
  // Stage skipping: after stage skip_after the next stage run is skip_to (Workload::next_stage).
  std::uint32_t skip_after = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t skip_to = 0;
  // Benchmarks: when these stages start, rank 0 prints its peak memory and the sizes of the checkpoint
  // and block journal of `output`.
  std::vector<std::uint32_t> report_stages = {};
  std::string output = {};
};

class ChainWorkload final : public runtime::Workload {
 public:
  explicit ChainWorkload(ChainSettings settings) : settings_(settings) {}

  store::ResultLayout layout() const override;
  std::uint32_t stage_count() const override { return settings_.stages; }
  std::uint64_t item_count(std::uint32_t) const override { return settings_.items; }
  Bytes stage_context(std::uint32_t stage, const ItemResults& kept) const override;
  Bytes item_input(std::uint32_t stage, std::uint64_t item, const ItemResults& kept) const override;
  Bytes compute(const runtime::ItemTask& task) const override;
  std::vector<store::Block> blocks(WorkItemId id, const Bytes& result) const override;
  std::uint32_t next_stage(std::uint32_t completed, const ItemResults&) const override {
    return completed == settings_.skip_after ? settings_.skip_to : completed + 1;
  }
  // The next stage reads every result of this one; the last stage's results no stage reads.
  std::uint32_t kept_through(WorkItemId id) const override {
    return id.stage + 1 < settings_.stages ? id.stage + 1 : id.stage;
  }
  void fold_summary(Bytes& summary, WorkItemId id, const Bytes& result) const override;
  std::string headline(const Bytes& summary) const override;

 private:
  struct Result {
    std::uint64_t value = 0, random = 0;
  };
  struct Summary {
    std::uint64_t results = 0, xor_of_values = 0;
    std::uint64_t results_in_signal_stage = 0;
  };
  static Result decode(const Bytes& bytes);
  // The stage run before `stage` (stage - 1 unless a skip landed on it).
  std::uint32_t previous(std::uint32_t stage) const {
    return stage == settings_.skip_to && settings_.skip_after < stage ? settings_.skip_after : stage - 1;
  }
  void maybe_raise(std::uint32_t stage, std::uint64_t collected) const;
  void report(std::uint32_t stage) const;

  ChainSettings settings_;
};

// This process's peak resident memory (VmHWM), in KiB.
long peak_rss_kib();

}  // namespace pbrfit::testing
