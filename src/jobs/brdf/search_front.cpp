// The Pareto front of a genBRDF search (brdf_search_workload.hpp): error vs tree size over every
// generation, and the culling of the knee's sub-expressions at the end (Brady et al., section 1).
#include <cmath>
#include <span>
#include <stdexcept>

#include "pbrfit/jobs/brdf/brdf_inputs.hpp"
#include "pbrfit/jobs/brdf/candidate_score.hpp"
#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "front_knee.hpp"
#include "search_records.hpp"

namespace pbrfit::jobs::brdf {
namespace {

constexpr std::size_t cull_budget = 60;    // candidate trees scored while culling
constexpr double cull_tolerance = 1e-3;    // a culled tree may be this much worse, relatively

bool dominates(const ScoredTree& a, const ScoredTree& b) {
  return a.error <= b.error && a.size() <= b.size() && (a.error < b.error || a.size() < b.size());
}

// The non-dominated trees of front + candidates (the earlier kept on equal objectives), and those of the
// candidates that made it. Abandoned candidates, whose errors are lower bounds, stay out.
FrontRecord merged(std::vector<ScoredTree> front, const std::vector<ScoredTree>& candidates,
                   const std::vector<std::uint8_t>& abandoned) {
  FrontRecord out;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const ScoredTree& c = candidates[k];
    if (!std::isfinite(c.error) || abandoned[k]) continue;
    bool beaten = false;
    for (const auto& f : front) beaten = beaten || dominates(f, c) || (f.error == c.error && f.size() == c.size());
    if (beaten) continue;
    std::erase_if(front, [&](const ScoredTree& f) { return dominates(c, f); });
    front.push_back(c);
    out.additions.push_back(c);
  }
  std::stable_sort(front.begin(), front.end(), [](const auto& a, const auto& b) { return a.size() < b.size(); });
  std::erase_if(out.additions, [&](const ScoredTree& a) {
    return std::none_of(front.begin(), front.end(), [&](const ScoredTree& f) { return f.tree == a.tree; });
  });
  out.front = std::move(front);
  return out;
}

FrontRecord merged(const FrontInput& input) {
  if (input.abandoned.size() != input.candidates.size()) throw std::logic_error("brdf search: a front input without its flags");
  return merged(input.previous.front, input.candidates, input.abandoned);
}

// Per island (population consecutive candidates each), the log's figures of the last generation.
std::vector<IslandStatistics> last_statistics(const std::vector<ScoredTree>& candidates,
                                              const std::vector<std::uint8_t>& abandoned, std::size_t population) {
  std::vector<IslandStatistics> out;
  for (std::size_t first = 0; first + population <= candidates.size(); first += population) {
    std::vector<double> errors, sizes;
    for (std::size_t k = first; k < first + population; ++k) errors.push_back(candidates[k].error), sizes.push_back(candidates[k].size());
    const auto island = std::span(abandoned).subspan(first, population);
    out.push_back(island_statistics(errors, sizes, island));
  }
  return out;
}

}  // namespace

// The front kept at generation - 1 and the members of generation - 1 with their errors.
FrontInput BrdfSearchWorkload::front_input(std::uint32_t generation, std::uint64_t, const Kept& kept) const {
  FrontInput input;
  if (generation == 0) return input;
  input.previous = kept.at<FrontRecord>("front", generation - 1, 0);
  for (auto& m : generation_members(generation - 1, kept)) {
    input.candidates.push_back({std::move(m.tree), m.error, generation - 1u});
    input.abandoned.push_back(m.abandoned);
  }
  return input;
}

// The front input after the last generation, as a next generation's front would have read it.
FrontInput BrdfSearchWorkload::last_front_input(std::uint32_t, std::uint64_t, const Kept& kept) const {
  return front_input(std::uint32_t(settings_.generations), 0, kept);
}

FrontRecord BrdfSearchWorkload::keep_front(const Task<Nothing, FrontInput>& task) const {
  if (task.step() == 0) return {};
  return merged(task.input);
}

FrontRecord BrdfSearchWorkload::keep_last_front(const Task<Nothing, FrontInput>& task) const {
  FrontRecord record = merged(task.input);
  record.last_generation = last_statistics(task.input.candidates, task.input.abandoned, settings_.population);
  if (!record.front.empty()) {
    const ScoredTree& knee = record.front[front_knee(record.front)];
    record.simplified = {knee, cull(knee, task)};
  }
  return record;
}

// Repeatedly replaces an operation's subtree by one of its operands or by 1 while the error stays within
// cull_tolerance of the knee's (each candidate refitted), until nothing more goes or the budget is spent.
ScoredTree BrdfSearchWorkload::cull(const ScoredTree& knee, const Task<Nothing, FrontInput>& task) const {
  const auto score = [&](const gp::SyntaxTree& tree) {
    const auto compiled = gp::compile(tree, brdf_parameter_count);
    return compiled ? score_candidate(*compiled, *settings_.data, settings_.fit, task.random(1)).error
                    : gp::worst_error;
  };
  ScoredTree best{knee.tree, score(knee.tree), knee.generation};
  const double allowed = best.error * (1.0 + cull_tolerance);
  std::size_t spent = 0;
  for (bool changed = true; changed && spent < cull_budget;) {
    changed = false;
    for (std::size_t i = 0; i < best.tree.size() && !changed && spent < cull_budget; ++i) {
      const auto& node = best.tree.nodes()[i];
      if (node.kind != gp::NodeKind::operation) continue;
      std::vector<gp::SyntaxTree> replacements = {gp::SyntaxTree({gp::SyntaxNode{}})};
      for (std::size_t child = i + 1; child < best.tree.subtree_end(i); child = best.tree.subtree_end(child))
        replacements.push_back(best.tree.subtree(child));
      for (const auto& r : replacements) {
        if (spent++ >= cull_budget || task.stop_requested()) break;
        const gp::SyntaxTree candidate = best.tree.with_subtree(i, r);
        const double error = score(candidate);
        if (error <= allowed) {
          best = {candidate, error, knee.generation};
          changed = true;
          break;
        }
      }
    }
  }
  return best;
}

}  // namespace pbrfit::jobs::brdf
