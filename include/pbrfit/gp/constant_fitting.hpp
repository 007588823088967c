#pragma once
// Fits the live constants of a program to the data with Nelder-Mead (optimize/nelder_mead.hpp), the
// structure fixed: each constant is searched in [c - w, c + w] with w = box_scale * max(1, |c|) around
// its current value c. Every error evaluation goes through the fitness evaluator, so it is counted in the
// run's budget.
//
// Contract: the returned program has the same structure and error <= the starting error (the start is
// kept when nothing better is found); at most max_evaluations evaluations (0 when the program has no
// live constant); deterministic.
#include <cstddef>
#include <vector>

#include "pbrfit/gp/fitness_evaluator.hpp"
#include "pbrfit/gp/program.hpp"
#include "pbrfit/gp/program_builder.hpp"

namespace pbrfit::gp {

struct ConstantFitOptions {
  std::size_t max_evaluations = 300;  // per program
  double box_scale = 4.0;
  double initial_step = 0.05;  // the starting simplex's offsets, relative to the box width
};

struct ConstantFitResult {
  Program program;
  double error = worst_error;
  std::size_t evaluations = 0;
};

// The constant operands of the live instructions, in program order.
std::vector<ConstantSlot> live_constant_slots(const Program& program);

// `start_error` is the program's current error (saves one evaluation).
ConstantFitResult fit_constants(const Program& program, double start_error, FitnessEvaluator& evaluator,
                                const ConstantFitOptions& options);

}  // namespace pbrfit::gp
