#include "pbrfit/gp/syntax_tree.hpp"

#include <cmath>
#include <stdexcept>

namespace pbrfit::gp {
namespace {

std::size_t children_of(const SyntaxNode& node) {
  return node.kind == NodeKind::operation ? std::size_t(arity(node.op)) : 0;
}

// Appends the leaf an operand that is not an instruction stands for (parameter >= 0: that parameter).
void expand(const Program& program, const Operand& operand, double constant, std::int64_t parameter,
            std::vector<SyntaxNode>& nodes);

void expand_instruction(const Program& program, std::size_t i, std::span<const std::vector<ConstantSlot>> slots,
                        std::vector<SyntaxNode>& nodes) {
  const Instruction& instruction = program.code[i];
  const auto parameter_of = [&](std::size_t operand) -> std::int64_t {
    for (std::size_t k = 0; k < slots.size(); ++k)
      for (const auto& slot : slots[k])
        if (slot.instruction == i && slot.operand == operand) return std::int64_t(k);
    return -1;
  };
  if (instruction.op != Opcode::identity) nodes.push_back({NodeKind::operation, instruction.op, 0, 0.0});
  for (int j = 0; j < arity(instruction.op); ++j) {
    const Operand& operand = instruction.operands[std::size_t(j)];
    if (operand.source == Source::instruction) {
      expand_instruction(program, operand.index, slots, nodes);
    } else {
      expand(program, operand, instruction.constants[std::size_t(j)], parameter_of(std::size_t(j)), nodes);
    }
  }
}

void expand(const Program&, const Operand& operand, double constant, std::int64_t parameter, std::vector<SyntaxNode>& nodes) {
  if (operand.source == Source::input) nodes.push_back({NodeKind::input, Opcode::identity, operand.index, 0.0});
  else if (parameter >= 0) nodes.push_back({NodeKind::parameter, Opcode::identity, std::uint16_t(parameter), 0.0});
  else nodes.push_back({NodeKind::constant, Opcode::identity, 0, constant});
}

// Builds node i's subtree with the builder and returns the argument that holds its value.
Argument build(const SyntaxTree& tree, std::size_t i, ProgramBuilder& builder) {
  const SyntaxNode& node = tree.nodes()[i];
  switch (node.kind) {
    case NodeKind::input: return input_argument(node.index);
    case NodeKind::parameter: return constant_argument(1.0, std::int64_t(node.index));
    case NodeKind::constant: return constant_argument(node.value);
    case NodeKind::operation: break;
  }
  std::array<Argument, max_operands> arguments{};
  std::size_t child = i + 1;
  for (int j = 0; j < arity(node.op); ++j) {
    arguments[std::size_t(j)] = build(tree, child, builder);
    child = tree.subtree_end(child);
  }
  return builder.append(node.op, arguments.data(), std::size_t(arity(node.op)));
}

// The fields a node's kind does not use take their defaults, so that equal trees compare equal.
void canonicalize(SyntaxNode& node) {
  if (node.kind != NodeKind::operation) node.op = Opcode::identity;
  if (node.kind != NodeKind::input && node.kind != NodeKind::parameter) node.index = 0;
  if (node.kind != NodeKind::constant) node.value = 1.0;
}

}  // namespace

SyntaxTree::SyntaxTree(std::vector<SyntaxNode> nodes) : nodes_(std::move(nodes)), ends_(nodes_.size()) {
  if (nodes_.empty()) throw std::invalid_argument("syntax tree: no nodes");
  // Right to left: a node's subtree ends where its last child's subtree ends.
  std::vector<std::size_t> pending;  // starts of complete subtrees to the right, nearest last
  for (std::size_t i = nodes_.size(); i-- > 0;) {
    SyntaxNode& node = nodes_[i];
    canonicalize(node);
    if (node.kind == NodeKind::constant && !std::isfinite(node.value)) throw std::invalid_argument("syntax tree: a constant is not finite");
    std::size_t end = i + 1;
    for (std::size_t c = 0; c < children_of(node); ++c) {
      if (pending.empty()) throw std::invalid_argument("syntax tree: an operation lacks operands");
      end = ends_[pending.back()];
      pending.pop_back();
    }
    ends_[i] = end;
    pending.push_back(i);
  }
  if (pending.size() != 1) throw std::invalid_argument("syntax tree: more than one root");
}

SyntaxTree SyntaxTree::subtree(std::size_t i) const {
  return SyntaxTree(std::vector<SyntaxNode>(nodes_.begin() + std::ptrdiff_t(i), nodes_.begin() + std::ptrdiff_t(ends_[i])));
}

SyntaxTree SyntaxTree::with_subtree(std::size_t i, const SyntaxTree& replacement) const {
  std::vector<SyntaxNode> out(nodes_.begin(), nodes_.begin() + std::ptrdiff_t(i));
  out.insert(out.end(), replacement.nodes().begin(), replacement.nodes().end());
  out.insert(out.end(), nodes_.begin() + std::ptrdiff_t(ends_[i]), nodes_.end());
  return SyntaxTree(std::move(out));
}

SyntaxTree tree_of(const Program& program, std::span<const std::vector<ConstantSlot>> parameter_slots) {
  std::vector<SyntaxNode> nodes;
  expand_instruction(program, program.length - 1u, parameter_slots, nodes);
  return SyntaxTree(std::move(nodes));
}

std::optional<CompiledTree> compile(const SyntaxTree& tree, std::size_t parameter_count) {
  ProgramBuilder builder(true);
  try {
    CompiledTree out{builder.finish(build(tree, 0, builder)), {}};
    for (std::size_t k = 0; k < parameter_count; ++k) out.parameter_slots.push_back(builder.slots_tagged(std::int64_t(k)));
    return out;
  } catch (const std::length_error&) {
    return std::nullopt;
  }
}

}  // namespace pbrfit::gp
