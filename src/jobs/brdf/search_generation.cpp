// The members of a generation of the genBRDF search (brdf_search_workload.hpp): the genomes and trees the
// islands bred, the distinct trees the evaluation stage fits (each once, however many slots hold it), and
// the errors mapped back to every slot.
#include <algorithm>
#include <stdexcept>
#include <unordered_map>

#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "search_records.hpp"

namespace pbrfit::jobs::brdf {
namespace {

using Evaluated = BrdfSearchWorkload::Evaluated;

std::string key_of(const gp::SyntaxTree& tree) {
  ByteWriter out;
  write_tree(out, tree);
  const Bytes bytes = out.take();
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

// Slot s holds distinct tree slot_tree[s]; distinct trees are numbered in order of first appearance.
struct DistinctTrees {
  std::vector<std::size_t> first_slot;
  std::vector<std::size_t> slot_tree;
};

DistinctTrees distinct(const std::vector<Evaluated>& members) {
  DistinctTrees out;
  std::unordered_map<std::string, std::size_t> seen;
  for (std::size_t s = 0; s < members.size(); ++s) {
    const auto [at, added] = seen.try_emplace(key_of(members[s].tree), out.first_slot.size());
    if (added) out.first_slot.push_back(s);
    out.slot_tree.push_back(at->second);
  }
  return out;
}

}  // namespace

std::vector<Evaluated> BrdfSearchWorkload::bred_members(std::uint32_t generation, const Kept& kept) const {
  std::vector<Evaluated> out;
  for (std::uint64_t i = 0; i < settings_.islands; ++i) {
    auto record = kept.at<BreedRecord>("breed", generation, i);
    for (std::size_t k = 0; k < record.genomes.size(); ++k)
      out.push_back({std::move(record.genomes[k]), std::move(record.trees[k])});
  }
  for (auto& m : out) m.size = double(m.tree.size());
  return out;
}

// Fits are abandoned above the worst island median of the generation bred from (none in generation 0,
// whose breeding records hold no statistics).
double BrdfSearchWorkload::abandon_threshold(std::uint32_t generation, const Kept& kept) const {
  if (!settings_.abandon_poor || generation == 0) return gp::worst_error;
  double threshold = 0.0;
  for (std::uint64_t i = 0; i < settings_.islands; ++i)
    threshold = std::max(threshold, kept.at<BreedRecord>("breed", generation, i).statistics.median_error);
  return threshold;
}

EvaluationContext BrdfSearchWorkload::evaluation_context(std::uint32_t generation, const Kept& kept) const {
  const auto members = bred_members(generation, kept);
  EvaluationContext context;
  context.abandon_above = abandon_threshold(generation, kept);
  for (const std::size_t s : distinct(members).first_slot) context.trees.push_back(members[s].tree);
  return context;
}

std::vector<Evaluated> BrdfSearchWorkload::generation_members(std::uint32_t generation, const Kept& kept) const {
  auto members = bred_members(generation, kept);
  const auto trees = distinct(members);
  std::vector<double> errors;
  std::vector<std::uint8_t> abandoned;
  for (std::uint64_t c = 0; c < chunks(); ++c) {
    const auto record = kept.at<EvaluationRecord>("evaluate", generation, c);
    errors.insert(errors.end(), record.errors.begin(), record.errors.end());
    abandoned.insert(abandoned.end(), record.abandoned.begin(), record.abandoned.end());
  }
  if (errors.size() != trees.first_slot.size())
    throw std::logic_error("brdf search: the evaluations do not match the generation's distinct trees");
  for (std::size_t s = 0; s < members.size(); ++s) {
    members[s].error = errors[trees.slot_tree[s]];
    members[s].abandoned = abandoned[trees.slot_tree[s]] != 0;
  }
  return members;
}

}  // namespace pbrfit::jobs::brdf
