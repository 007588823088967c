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
//
// Slots are then reused: a step writes the most recently freed slot, one whose value no later step reads,
// never one of its own operands. A tree needs about as many slots as it is deep rather than one per step,
// so a block's values stay in the first-level cache (64 steps of 512 float rows would fill 128 KiB).
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
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

// Gives each step's result, in step order, the slot freed most recently or else a new one; a slot is freed
// once the last step reading its value has run, so results with disjoint lifetimes share a slot. A step's
// operands are freed after its own slot is chosen, so `out` never aliases an operand. `slots` is where the schedule's slot pointers point,
// block_size values per slot, indexed until now by the step that made them.
template <class T>
void reuse_slots(BlockSchedule<T>& schedule, T* slots, std::size_t block_size) {
  constexpr std::uint8_t none = 0xff;
  const T* const slots_end = slots + max_program_length * block_size;
  auto slot_of = [&](const T* p) -> std::size_t {
    const std::less<const T*> before;  // a total order on pointers into different arrays, unlike <
    return !before(p, slots) && before(p, slots_end) ? static_cast<std::size_t>(p - slots) / block_size : none;
  };
  // last_reader[slot]: the last step reading it; the output's slot is read after every step.
  std::array<std::uint8_t, max_program_length> last_reader;
  last_reader.fill(none);
  for (std::size_t s = 0; s < schedule.step_count; ++s)
    for (const BlockPointer<T>& operand : schedule.steps[s].operands)
      if (const std::size_t slot = slot_of(operand.base); slot != none && operand.base != schedule.steps[s].out)
        last_reader[slot] = static_cast<std::uint8_t>(s);
  const std::size_t output_slot = slot_of(schedule.output.base);
  std::array<std::uint8_t, max_program_length> renamed;  // old slot -> new slot
  std::array<std::uint8_t, max_program_length> free_slots;
  std::size_t free_count = 0, slot_count = 0;
  for (std::size_t s = 0; s < schedule.step_count; ++s) {
    Step<T>& step = schedule.steps[s];
    const std::size_t old_out = slot_of(step.out);
    const std::uint8_t out = free_count > 0 ? free_slots[--free_count] : static_cast<std::uint8_t>(slot_count++);
    renamed[old_out] = out;
    for (BlockPointer<T>& operand : step.operands) {
      const std::size_t slot = slot_of(operand.base);
      if (slot == none) continue;
      const bool own = operand.base == step.out;  // an operand beyond the arity
      operand.base = slots + block_size * (own ? out : renamed[slot]);
      // The operand's slot is free once this, its last reader, has run (each slot is freed once, and the
      // output's never).
      if (!own && last_reader[slot] == s && slot != output_slot) {
        last_reader[slot] = none;
        free_slots[free_count++] = renamed[slot];
      }
    }
    step.out = slots + block_size * out;
  }
  if (output_slot != none) schedule.output.base = slots + block_size * renamed[output_slot];
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
  reuse_slots(schedule, slots.data(), block_size);
  return schedule;
}

}  // namespace pbrfit::gp::detail
