#include "front_knee.hpp"

#include <algorithm>
#include <vector>

#include "pbrfit/gp/pareto.hpp"

namespace pbrfit::jobs::brdf {
namespace {

bool reads_an_input(const gp::SyntaxTree& tree) {
  return std::ranges::any_of(tree.nodes(), [](const gp::SyntaxNode& n) { return n.kind == gp::NodeKind::input; });
}

}  // namespace

std::size_t front_knee(std::span<const ScoredTree> front) {
  double constant_error = gp::worst_error;
  for (const auto& f : front)
    if (!reads_an_input(f.tree)) constant_error = std::min(constant_error, f.error);
  std::vector<std::size_t> counted;
  for (std::size_t k = 0; k < front.size(); ++k)
    if (front[k].error < constant_error) counted.push_back(k);
  if (counted.empty())
    for (std::size_t k = 0; k < front.size(); ++k) counted.push_back(k);
  std::vector<gp::Fitness> fitness;
  for (const std::size_t k : counted) fitness.push_back({front[k].error, front[k].size(), 0.0, true});
  return counted[gp::knee_index(fitness)];
}

}  // namespace pbrfit::jobs::brdf
