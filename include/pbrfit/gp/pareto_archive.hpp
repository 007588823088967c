#pragma once
// Every non-dominated program a run has seen (Pesce & Iwanicki 2015, section 5.1), with the generation it
// appeared in, so the trade-off between error and cost can be chosen after the run.
//
// Invariants: no entry dominates another and no two entries have the same objectives (the first one seen
// is kept); every entry is evaluated with a finite error; entries are sorted by cost, then error, then
// piecewise count, so with two objectives the error falls along the list. The result of a sequence of
// insertions depends only on the entries and their order.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pbrfit/gp/fitness.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

struct ArchiveEntry {
  Program program;
  Fitness fitness;
  std::uint64_t generation = 0;  // when the program was first evaluated
};

class ParetoArchive {
 public:
  explicit ParetoArchive(std::size_t objective_count = 2);

  // Adds the entry unless it is unevaluated, has a non-finite error, or an entry dominates it or has the
  // same objectives; removes the entries it dominates. True when it was added.
  bool insert(const ArchiveEntry& entry);
  // Whether insert() would add an entry with this fitness (a cheap test before building the entry).
  bool admits(const Fitness& fitness) const;
  void insert_all(std::span<const ArchiveEntry> entries);

  const std::vector<ArchiveEntry>& entries() const { return entries_; }
  std::size_t size() const { return entries_.size(); }
  std::size_t objective_count() const { return objective_count_; }

 private:
  std::size_t objective_count_;
  std::vector<ArchiveEntry> entries_;
};

}  // namespace pbrfit::gp
