#pragma once
// A program prepared for the batch interpreter: its live instructions as steps whose operands are block
// pointers. An input operand points into its data column (it advances with the block's first row); an
// instruction operand points to that instruction's slot block and a constant operand to a block filled
// with its value (neither advances). Identity instructions become aliases and emit no step.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "pbrfit/gp/live_code.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp::detail {

// Members are left uninitialized by default: a schedule is rebuilt for every evaluation.
template <class T>
struct BlockPointer {
  const T* base;
  std::size_t advance;  // 1 for a data column, 0 for a slot or constant block
  bool constant;        // a constant's block: every value is base[0], which kernels may read once

  const T* at(std::size_t first_row) const { return base + first_row * advance; }
};

template <class T>
struct Step {
  Opcode op;
  std::array<BlockPointer<T>, max_operands> operands;  // operands beyond the arity point to the output
  T* out;
};

template <class T>
struct BlockSchedule {
  std::array<Step<T>, max_program_length> steps;
  std::size_t step_count;
  BlockPointer<T> output;
};

// Slots and constant blocks are block_size values each, max_program_length and max_program_length *
// max_operands of them; constant blocks of live operands are filled here.
template <class T>
BlockSchedule<T> schedule_blocks(const Program& program, const Eigen::Array<T, Eigen::Dynamic, Eigen::Dynamic>& columns,
                                 std::vector<T>& slots, std::vector<T>& constant_blocks, std::size_t block_size) {
  BlockSchedule<T> schedule;
  schedule.step_count = 0;
  std::array<BlockPointer<T>, max_program_length> location;
  std::size_t constants_used = 0;
  const LiveMask live = live_instructions(program);
  for (std::size_t i = 0; i < program.length; ++i) {
    if (!live.test(i)) continue;
    const Instruction& instruction = program.code[i];
    Step<T> step;
    step.op = instruction.op;
    step.out = slots.data() + block_size * schedule.step_count;
    step.operands.fill({step.out, 0, false});
    for (int j = 0; j < arity(instruction.op); ++j) {
      const Operand& operand = instruction.operands[j];
      if (operand.source == Source::input) {
        step.operands[j] = {columns.col(operand.index).data(), 1, false};
      } else if (operand.source == Source::instruction) {
        step.operands[j] = location[operand.index];
      } else {
        T* block = constant_blocks.data() + block_size * constants_used++;
        std::fill(block, block + block_size, static_cast<T>(instruction.constants[j]));
        step.operands[j] = {block, 0, true};
      }
    }
    if (instruction.op == Opcode::identity) {
      location[i] = step.operands[0];
      continue;
    }
    location[i] = {step.out, 0, false};
    schedule.steps[schedule.step_count++] = step;
  }
  schedule.output = location[program.length - 1u];
  return schedule;
}

}  // namespace pbrfit::gp::detail
