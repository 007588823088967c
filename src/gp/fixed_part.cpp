#include "pbrfit/gp/fixed_part.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/live_code.hpp"

namespace pbrfit::gp {
namespace {

// Instruction i must stay in the program: it depends on a parameter (its own constant slots, or an
// operand that does) or is marked to be kept.
std::vector<bool> parameter_dependent(const Program& program, std::span<const std::vector<ConstantSlot>> slots,
                                      std::vector<bool> varies) {
  for (const auto& list : slots)
    for (const auto& slot : list) varies[slot.instruction] = true;
  for (std::size_t i = 0; i < program.length; ++i) {
    const Instruction& ins = program.code[i];
    for (int j = 0; j < arity(ins.op); ++j)
      if (ins.operands[j].source == Source::instruction && varies[ins.operands[j].index]) varies[i] = true;
  }
  return varies;
}

// The program with instruction `last` as its output.
Program truncated(const Program& program, std::size_t last) {
  Program out;
  out.length = std::uint16_t(last + 1);
  for (std::size_t i = 0; i <= last; ++i) out.code[i] = program.code[i];
  return out;
}

// The dataset with the values of the fixed instructions as extra columns, or the first fixed instruction
// whose values are not all finite (a dataset holds only finite values).
std::variant<Dataset, std::size_t> with_columns(const Program& program, const std::vector<std::size_t>& fixed,
                                                const Dataset& dataset) {
  Dataset out = dataset;
  const Eigen::Index inputs = dataset.inputs.cols(), rows = dataset.inputs.rows();
  out.inputs.conservativeResize(rows, inputs + Eigen::Index(fixed.size()));
  if (fixed.empty()) return out;
  BatchInterpreter<double> interpreter(dataset);
  std::vector<double> values(std::size_t(rows), 0.0);
  for (std::size_t k = 0; k < fixed.size(); ++k) {
    interpreter.evaluate(truncated(program, fixed[k]), values);
    if (!std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); })) return fixed[k];
    for (Eigen::Index r = 0; r < rows; ++r) out.inputs(r, inputs + Eigen::Index(k)) = values[std::size_t(r)];
  }
  return out;
}

// One folding, keeping the instructions marked in `kept` in the program.
std::variant<FoldedFit, std::size_t> folded(const Program& program, std::span<const std::vector<ConstantSlot>> parameter_slots,
                                            const Dataset& dataset, const std::vector<bool>& kept) {
  const auto live = live_instructions(program);
  const auto varies = parameter_dependent(program, parameter_slots, kept);
  std::vector<std::size_t> fixed;                             // instructions that become columns
  std::vector<int> column(program.length, -1), moved(program.length, -1);
  const auto column_of = [&](std::size_t i) {
    if (column[i] < 0) column[i] = int(dataset.input_count() + fixed.size()), fixed.push_back(i);
    return std::size_t(column[i]);
  };
  FoldedFit out;
  const std::size_t last = program.length - 1u;
  if (!varies[last]) {
    out.program.length = 1;
    out.program.code[0].operands[0] = input_operand(column_of(last));
  }
  for (std::size_t i = 0; i < program.length && varies[last]; ++i) {
    if (!live[i] || !varies[i]) continue;
    Instruction ins = program.code[i];
    for (int j = 0; j < arity(ins.op); ++j) {
      Operand& operand = ins.operands[j];
      if (operand.source != Source::instruction) continue;
      operand = varies[operand.index] ? result_operand(std::size_t(moved[operand.index])) : input_operand(column_of(operand.index));
    }
    moved[i] = out.program.length;
    out.program.code[out.program.length++] = ins;
  }
  for (const auto& list : parameter_slots) {
    auto& mapped = out.parameter_slots.emplace_back();
    for (const auto& slot : list)
      if (moved[slot.instruction] >= 0) mapped.push_back({std::uint16_t(moved[slot.instruction]), slot.operand});
  }
  auto columns = with_columns(program, fixed, dataset);
  if (const auto* bad = std::get_if<std::size_t>(&columns)) return *bad;
  out.dataset = std::move(std::get<Dataset>(columns));
  return out;
}

}  // namespace

FoldedFit fold_fixed_part(const Program& program, std::span<const std::vector<ConstantSlot>> parameter_slots,
                          const Dataset& dataset) {
  std::vector<bool> kept(program.length, false);
  for (;;) {  // each round keeps one more instruction, so this ends
    auto attempt = folded(program, parameter_slots, dataset, kept);
    if (auto* fit = std::get_if<FoldedFit>(&attempt)) return std::move(*fit);
    kept[std::get<std::size_t>(attempt)] = true;
  }
}

}  // namespace pbrfit::gp
