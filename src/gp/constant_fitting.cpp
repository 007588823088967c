#include "pbrfit/gp/constant_fitting.hpp"

#include <algorithm>
#include <cmath>

#include "pbrfit/gp/live_code.hpp"
#include "pbrfit/optimize/evaluator.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"

namespace pbrfit::gp {

std::vector<ConstantSlot> live_constant_slots(const Program& program) {
  const LiveMask live = live_instructions(program);
  std::vector<ConstantSlot> slots;
  for (std::size_t i = 0; i < program.length; ++i) {
    for (int j = 0; live.test(i) && j < arity(program.code[i].op); ++j) {
      if (program.code[i].operands[j].source == Source::constant) {
        slots.push_back({static_cast<std::uint16_t>(i), static_cast<std::uint8_t>(j)});
      }
    }
  }
  return slots;
}

ConstantFitResult fit_constants(const Program& program, double start_error, FitnessEvaluator& evaluator,
                                const ConstantFitOptions& options) {
  ConstantFitResult result{program, start_error, 0};
  const std::vector<ConstantSlot> slots = live_constant_slots(program);
  if (slots.empty() || options.max_evaluations < 2) return result;
  optimize::Bounds box;
  std::vector<double> start;
  for (const ConstantSlot& slot : slots) {
    const double value = program.code[slot.instruction].constants[slot.operand];
    const double reach = options.box_scale * std::max(1.0, std::abs(value));
    box.lower.push_back(value - reach);
    box.upper.push_back(value + reach);
    start.push_back(value);
  }
  Program trial = program;
  auto write = [&](Program& target, std::span<const double> x) {
    for (std::size_t k = 0; k < slots.size(); ++k) target.code[slots[k].instruction].constants[slots[k].operand] = x[k];
  };
  const optimize::Objective objective = [&](std::span<const double> x) {
    write(trial, x);
    return evaluator.error(trial);
  };
  optimize::NelderMeadOptions nelder_mead;
  nelder_mead.initial_step = options.initial_step;
  nelder_mead.restart_step = options.initial_step;
  optimize::Evaluator counted(objective, options.max_evaluations);
  const auto run = optimize::nelder_mead(counted, box, start, nelder_mead, start_error);
  result.evaluations = counted.used();
  if (run.best.value < start_error) {
    write(result.program, run.best.x);
    result.error = run.best.value;
  }
  return result;
}

}  // namespace pbrfit::gp
