#pragma once
// Syntax trees, edit genomes and scored trees as bytes (core/bytes.hpp), for work items and checkpoints.
//
// Contract: reading validates what it reads (opcodes, node kinds, input and parameter indices against the
// given counts, finite constants, well-formed trees) and throws ByteFormatError otherwise.
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/gp/edit_evolution.hpp"
#include "pbrfit/gp/syntax_tree.hpp"

namespace pbrfit::jobs::brdf {

// A tree with its search objectives and the generation it was first evaluated in.
struct ScoredTree {
  gp::SyntaxTree tree{{gp::SyntaxNode{}}};
  double error = gp::worst_error;
  std::uint64_t generation = 0;
  double size() const { return double(tree.size()); }
};

void write_tree(ByteWriter& out, const gp::SyntaxTree& tree);
gp::SyntaxTree read_tree(ByteReader& in, std::size_t inputs, std::size_t parameters);
void write_genome(ByteWriter& out, const gp::Genome& genome);
gp::Genome read_genome(ByteReader& in);
void write_scored(ByteWriter& out, const std::vector<ScoredTree>& trees);
std::vector<ScoredTree> read_scored(ByteReader& in, std::size_t inputs, std::size_t parameters);

}  // namespace pbrfit::jobs::brdf
