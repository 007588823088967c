#pragma once
// Syntax trees, edit genomes and scored trees as bytes (core/bytes.hpp), for work items and checkpoints,
// and as core/serial.hpp types: a gp::SyntaxTree sent through it is a genBRDF tree (brdf_inputs.hpp's
// inputs and parameters), the only kind of tree pbrfit sends whole (symreg sends gp's program bytes).
//
// Contract: reading validates what it reads (opcodes, node kinds, edit kinds, input and parameter indices
// against the given counts, finite constants, well-formed trees) and throws ByteFormatError otherwise.
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/core/serial.hpp"
#include "pbrfit/gp/edit_evolution.hpp"
#include "pbrfit/gp/syntax_tree.hpp"
#include "pbrfit/jobs/brdf/brdf_inputs.hpp"

namespace pbrfit::jobs::brdf {

// A tree with its search objectives and the generation it was first evaluated in.
struct ScoredTree {
  gp::SyntaxTree tree{{gp::SyntaxNode{}}};
  double error = gp::worst_error;
  std::uint64_t generation = 0;
  double size() const { return double(tree.size()); }
  template <class Archive>
  void serialize(Archive& archive) {
    archive(tree, error, generation);
  }
};

void write_tree(ByteWriter& out, const gp::SyntaxTree& tree);
gp::SyntaxTree read_tree(ByteReader& in, std::size_t inputs, std::size_t parameters);
gp::Edit read_edit(ByteReader& in);  // as Serial<gp::Edit> writes it

}  // namespace pbrfit::jobs::brdf

namespace pbrfit {

template <>
struct Serial<gp::SyntaxTree> {
  static void write(SerialWriter& w, const gp::SyntaxTree& tree) { jobs::brdf::write_tree(w.bytes(), tree); }
  static gp::SyntaxTree read(SerialReader& r) {
    return jobs::brdf::read_tree(r.bytes(), jobs::brdf::brdf_input_count, jobs::brdf::brdf_parameter_count);
  }
};

template <>
struct Serial<gp::Edit> {
  static void write(SerialWriter& w, const gp::Edit& edit) { w(edit.kind, edit.first, edit.second); }
  static gp::Edit read(SerialReader& r) { return jobs::brdf::read_edit(r.bytes()); }
};

}  // namespace pbrfit
