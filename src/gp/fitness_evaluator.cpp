#include "pbrfit/gp/fitness_evaluator.hpp"

namespace pbrfit::gp {

FitnessEvaluator::FitnessEvaluator(const Dataset& dataset, const FitnessOptions& options) : options_(options) {
  if (options.precision == Precision::float32) {
    single_ = std::make_unique<BatchInterpreter<float>>(dataset, options.error);
  } else {
    double_ = std::make_unique<BatchInterpreter<double>>(dataset, options.error);
  }
}

FitnessEvaluator::~FitnessEvaluator() = default;

double FitnessEvaluator::error(const Program& program) {
  ++evaluations_;
  return single_ ? single_->error(program) : double_->error(program);
}

Fitness FitnessEvaluator::operator()(const Program& program) {
  Fitness fitness;
  fitness.error = error(program);
  std::size_t piecewise = 0;
  cost_and_piecewise(program, live_instructions(program), options_.costs, fitness.cost, piecewise);
  fitness.piecewise = static_cast<double>(piecewise);
  fitness.evaluated = true;
  return fitness;
}

}  // namespace pbrfit::gp
