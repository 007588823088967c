#pragma once
// A program prepared for the batch interpreter: its live instructions as steps whose operands are block
// pointers. An input operand points into its data column (it advances with the block's first row); an
// instruction operand points to that instruction's slot block and a constant operand to a block filled
// with its value (neither advances). Identity instructions become aliases and emit no step.
//
// Pairs of arithmetic steps where the second is the only reader of the first's result become one fused
// step: out = second(op(a, b), c), the intermediate kept in a register instead of stored to its block and
// loaded again. The operations and their order are the same, so are the values, bitwise (a block loop is
// bound by its loads and stores; a tree's post-order puts most operators right after an operand's own).
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
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
  // A fused pair: out = second(op(operands[0], operands[1]), operands[2]), or second(operands[2], op(...))
  // when the intermediate was the second's right operand. Opcode::identity: not fused.
  Opcode second;
  bool intermediate_left;
};

// The operators a pair may fuse (block_kernels.hpp's with_arithmetic knows each of them).
constexpr bool fusable(Opcode op) {
  return op == Opcode::add || op == Opcode::sub || op == Opcode::mul || op == Opcode::div;
}

template <class T>
struct BlockSchedule {
  std::array<Step<T>, max_program_length> steps;
  std::size_t step_count;
  BlockPointer<T> output;
};

// Fuses each step into the next where both are fusable and the next is the only reader of the step's
// result, reading it once (x * x reads it twice); steps keep their order, a fused step the second's slot.
template <class T>
void fuse_pairs(BlockSchedule<T>& schedule, const std::array<std::uint8_t, max_program_length>& readers) {
  std::size_t kept = 0;
  for (std::size_t s = 0; s < schedule.step_count; ++s) {
    Step<T> step = schedule.steps[s];
    if (s + 1 < schedule.step_count && fusable(step.op) && readers[s] == 1 && fusable(schedule.steps[s + 1].op)) {
      const Step<T>& next = schedule.steps[s + 1];
      const bool left = next.operands[0].base == step.out;
      if (left || next.operands[1].base == step.out) {
        step.second = next.op;
        step.intermediate_left = left;
        step.operands[2] = next.operands[left ? 1 : 0];
        step.out = next.out;
        ++s;
      }
    }
    schedule.steps[kept++] = step;
  }
  schedule.step_count = kept;
}

// Slots and constant blocks are block_size values each, max_program_length and max_program_length *
// max_operands of them; constant blocks of live operands are filled here.
template <class T>
BlockSchedule<T> schedule_blocks(const Program& program, const Eigen::Array<T, Eigen::Dynamic, Eigen::Dynamic>& columns,
                                 std::vector<T>& slots, std::vector<T>& constant_blocks, std::size_t block_size) {
  BlockSchedule<T> schedule;
  schedule.step_count = 0;
  std::array<BlockPointer<T>, max_program_length> location;
  constexpr std::uint8_t no_step = 0xff;
  std::array<std::uint8_t, max_program_length> producer;  // the step whose slot location[i] is, or no_step
  std::array<std::uint8_t, max_program_length> readers{};  // by step: operand references, the output's too
  std::size_t constants_used = 0;
  const LiveMask live = live_instructions(program);
  for (std::size_t i = 0; i < program.length; ++i) {
    if (!live.test(i)) continue;
    const Instruction& instruction = program.code[i];
    Step<T> step;
    step.op = instruction.op;
    step.out = slots.data() + block_size * schedule.step_count;
    step.second = Opcode::identity;
    step.intermediate_left = false;
    step.operands.fill({step.out, 0, false});
    producer[i] = no_step;
    for (int j = 0; j < arity(instruction.op); ++j) {
      const Operand& operand = instruction.operands[j];
      if (operand.source == Source::input) {
        step.operands[j] = {columns.col(operand.index).data(), 1, false};
      } else if (operand.source == Source::instruction) {
        step.operands[j] = location[operand.index];
        const std::uint8_t from = producer[operand.index];
        producer[i] = from;  // kept only by an identity, whose own readers count instead of it
        if (from != no_step && instruction.op != Opcode::identity) ++readers[from];
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
    producer[i] = static_cast<std::uint8_t>(schedule.step_count);
    location[i] = {step.out, 0, false};
    schedule.steps[schedule.step_count++] = step;
  }
  schedule.output = location[program.length - 1u];
  if (producer[program.length - 1u] != no_step) ++readers[producer[program.length - 1u]];
  fuse_pairs(schedule, readers);
  return schedule;
}

}  // namespace pbrfit::gp::detail
