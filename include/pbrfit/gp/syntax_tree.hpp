#pragma once
// An expression as a tree, the representation genBRDF's edits act on (Brady et al., section 3.3): nodes in
// preorder, each operation followed by its operands' subtrees; leaves are inputs (data columns),
// parameters (fitted per material and channel) and constants. A tree compiles to a linear program
// (program.hpp) whose equal sub-expressions are shared, and a program expands back to a tree.
//
// Invariants: a SyntaxTree is well formed (the constructor throws std::invalid_argument otherwise): every
// operation has exactly arity(op) subtrees after it and nothing follows the root's subtree; it has at least
// one node; constants are finite. subtree_end(i) is one past node i's last descendant.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "pbrfit/gp/program.hpp"
#include "pbrfit/gp/program_builder.hpp"

namespace pbrfit::gp {

enum class NodeKind : std::uint8_t { operation, input, parameter, constant };

struct SyntaxNode {
  NodeKind kind = NodeKind::constant;
  Opcode op = Opcode::identity;  // operations
  std::uint16_t index = 0;       // inputs and parameters
  double value = 1.0;            // constants
  bool operator==(const SyntaxNode&) const = default;
};

class SyntaxTree {
 public:
  explicit SyntaxTree(std::vector<SyntaxNode> nodes);

  std::size_t size() const { return nodes_.size(); }
  const std::vector<SyntaxNode>& nodes() const { return nodes_; }
  std::size_t subtree_end(std::size_t i) const { return ends_[i]; }
  // Whether node j lies in node i's subtree (i included).
  bool contains(std::size_t i, std::size_t j) const { return j >= i && j < ends_[i]; }
  SyntaxTree subtree(std::size_t i) const;
  // This tree with node i's subtree replaced by `replacement`.
  SyntaxTree with_subtree(std::size_t i, const SyntaxTree& replacement) const;
  // Equal trees compare equal: the constructor resets the fields a node's kind does not use.
  bool operator==(const SyntaxTree& other) const { return nodes_ == other.nodes_; }

 private:
  std::vector<SyntaxNode> nodes_;
  std::vector<std::size_t> ends_;
};

// The tree of a program's output; constants in parameter_slots[k] become parameter k.
SyntaxTree tree_of(const Program& program, std::span<const std::vector<ConstantSlot>> parameter_slots = {});

struct CompiledTree {
  Program program;
  std::vector<std::vector<ConstantSlot>> parameter_slots;  // one list per parameter, possibly empty
};
// The program of a tree with `parameter_count` parameters (each initially 1); nullopt when it needs more
// than max_program_length instructions even with its common sub-expressions shared.
std::optional<CompiledTree> compile(const SyntaxTree& tree, std::size_t parameter_count);

}  // namespace pbrfit::gp
