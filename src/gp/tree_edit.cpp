#include "pbrfit/gp/tree_edit.hpp"

#include <algorithm>

namespace pbrfit::gp {
namespace {

SyntaxTree swapped(const SyntaxTree& tree, std::size_t i, std::size_t j) {
  if (i > j) std::swap(i, j);
  if (tree.contains(i, j)) return tree;
  const SyntaxTree left = tree.subtree(i), right = tree.subtree(j);
  return tree.with_subtree(j, left).with_subtree(i, right);  // j first: it lies after i's subtree
}

SyntaxNode scalar_production(std::size_t k, const EditGrammar& g) {
  if (k < g.inputs) return {NodeKind::input, Opcode::identity, std::uint16_t(k), 0.0};
  k -= g.inputs;
  if (k < g.parameters) return {NodeKind::parameter, Opcode::identity, std::uint16_t(k), 0.0};
  return {NodeKind::constant, Opcode::identity, 0, g.constants[k - g.parameters]};
}

// Another member of `choices` than `current`, picked by `pick`; `current` itself when there is no other.
template <class T>
T another(const std::vector<T>& choices, const T& current, std::uint32_t pick) {
  std::vector<T> others;
  for (const T& c : choices)
    if (!(c == current)) others.push_back(c);
  return others.empty() ? current : others[pick % others.size()];
}

SyntaxNode replaced(const SyntaxNode& node, std::uint32_t pick, const EditGrammar& g) {
  if (node.kind == NodeKind::operation) {
    const OperatorSet& set = arity(node.op) == 1 ? g.unary : g.binary;
    if (arity(node.op) > 2 || !set.contains(node.op)) return node;
    SyntaxNode out = node;
    out.op = another(set.members(), node.op, pick);
    return out;
  }
  std::vector<SyntaxNode> scalars;
  for (std::size_t k = 0; k < g.inputs + g.parameters + g.constants.size(); ++k) scalars.push_back(scalar_production(k, g));
  return another(scalars, node, pick);
}

SyntaxTree with_node(const SyntaxTree& tree, std::size_t i, const SyntaxNode& node) {
  std::vector<SyntaxNode> nodes = tree.nodes();
  nodes[i] = node;
  return SyntaxTree(std::move(nodes));
}

const SyntaxTree& one() {
  static const SyntaxTree tree({{NodeKind::constant, Opcode::identity, 0, 1.0}});
  return tree;
}

}  // namespace

SyntaxTree apply_edit(const SyntaxTree& tree, const Edit& edit, const EditGrammar& g) {
  const std::size_t n = tree.size(), i = edit.first % n;
  SyntaxTree out = tree;
  switch (edit.kind) {
    case EditKind::swap: out = swapped(tree, i, edit.second % n); break;
    case EditKind::insert:
      if (!g.codebank.empty()) out = tree.with_subtree(edit.second % n, g.codebank[edit.first % g.codebank.size()]);
      break;
    case EditKind::replace: out = with_node(tree, i, replaced(tree.nodes()[i], edit.second, g)); break;
    case EditKind::remove: out = tree.with_subtree(i, one()); break;
  }
  return out.size() > g.max_nodes ? tree : out;
}

SyntaxTree reify(const SyntaxTree& seed, std::span<const Edit> genome, const EditGrammar& g) {
  SyntaxTree tree = seed;
  for (const Edit& edit : genome) tree = apply_edit(tree, edit, g);
  return tree;
}

Edit random_edit(RandomStream& random) {
  const auto kind = static_cast<EditKind>(random.below(4));
  const auto first = std::uint32_t(random.next_u64()), second = std::uint32_t(random.next_u64());
  return {kind, first, second};
}

std::vector<SyntaxTree> codebank_of(std::span<const SyntaxTree> seeds) {
  std::vector<SyntaxTree> bank;
  for (const SyntaxTree& seed : seeds)
    for (std::size_t i = 0; i < seed.size(); ++i) {
      SyntaxTree sub = seed.subtree(i);
      if (std::find(bank.begin(), bank.end(), sub) == bank.end()) bank.push_back(std::move(sub));
    }
  return bank;
}

}  // namespace pbrfit::gp
