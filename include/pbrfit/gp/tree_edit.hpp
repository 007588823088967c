#pragma once
// The edits of genBRDF (Brady et al., section 3.3) on a syntax tree (syntax_tree.hpp). An edit names its
// nodes by two numbers taken modulo the tree's size when it is applied, so any list of edits applies to any
// tree and a genome (an ordered list of edits) always reifies to a valid tree:
//  - swap: node first % n and node second % n exchange their subtrees (nothing happens when one lies in the
//    other's subtree);
//  - insert: node second % n's subtree becomes codebank[first % K], a sub-expression of the seed BRDFs;
//  - replace: node first % n becomes another production of its kind, chosen by second: a unary operator
//    another unary, a binary operator another binary (of the grammar's sets), a scalar (input, parameter or
//    constant) another scalar; its children are kept;
//  - remove: node first % n's subtree becomes the constant 1.
//
// Contract: apply_edit is a pure function of (tree, edit, grammar); a result larger than max_nodes leaves the
// tree unchanged (genomes cannot grow trees without bound).
#include <cstdint>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/operator_set.hpp"
#include "pbrfit/gp/syntax_tree.hpp"

namespace pbrfit::gp {

enum class EditKind : std::uint8_t { swap, insert, replace, remove };

struct Edit {
  EditKind kind = EditKind::remove;
  std::uint32_t first = 0;
  std::uint32_t second = 0;
  bool operator==(const Edit&) const = default;
};

struct EditGrammar {
  OperatorSet unary;    // Figure 4: - sin cos tan exp asin acos atan sqrt
  OperatorSet binary;   // + - * / max min pow
  std::size_t inputs = 0;
  std::size_t parameters = 0;
  std::vector<double> constants = {};  // 1, 2, pi, 4
  std::vector<SyntaxTree> codebank = {};
  std::size_t max_nodes = 256;
};

SyntaxTree apply_edit(const SyntaxTree& tree, const Edit& edit, const EditGrammar& grammar);
SyntaxTree reify(const SyntaxTree& seed, std::span<const Edit> genome, const EditGrammar& grammar);
Edit random_edit(RandomStream& random);
// Every distinct subtree of the seeds, in order of first appearance.
std::vector<SyntaxTree> codebank_of(std::span<const SyntaxTree> seeds);

}  // namespace pbrfit::gp
