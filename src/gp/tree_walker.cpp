#include "pbrfit/gp/tree_walker.hpp"

#include <stdexcept>
#include <vector>

#include "pbrfit/gp/semantics.hpp"

namespace pbrfit::gp {
namespace {

template <class T>
T walk(const Program& program, std::size_t node, std::span<const T> row) {
  const Instruction& instruction = program.code[node];
  T values[max_operands] = {T(0), T(0), T(0)};
  for (int j = 0; j < arity(instruction.op); ++j) {
    const Operand& operand = instruction.operands[j];
    switch (operand.source) {
      case Source::input:
        values[j] = row[operand.index];
        break;
      case Source::constant:
        values[j] = static_cast<T>(instruction.constants[j]);
        break;
      case Source::instruction:
        values[j] = walk(program, operand.index, row);
        break;
      case Source::none:
        break;
    }
  }
  return apply<T>(instruction.op, values[0], values[1], values[2]);
}

}  // namespace

template <class T>
T walk_tree(const Program& program, std::span<const T> row) {
  return walk(program, program.length - 1u, row);
}

template <class T>
void walk_tree(const Program& program, const Dataset& dataset, std::span<T> out) {
  if (out.size() != dataset.rows()) throw std::invalid_argument("walk_tree: one output per row");
  std::vector<T> row(dataset.input_count());
  for (std::size_t r = 0; r < dataset.rows(); ++r) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      row[c] = static_cast<T>(dataset.inputs(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)));
    }
    out[r] = walk_tree<T>(program, std::span<const T>(row));
  }
}

template float walk_tree<float>(const Program&, std::span<const float>);
template double walk_tree<double>(const Program&, std::span<const double>);
template void walk_tree<float>(const Program&, const Dataset&, std::span<float>);
template void walk_tree<double>(const Program&, const Dataset&, std::span<double>);

}  // namespace pbrfit::gp
