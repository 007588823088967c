#pragma once
// Computes the fitness of programs on one dataset with the batch interpreter of the run's precision, and
// counts every evaluation (one program over the whole dataset) against a budget.
//
// Contract: operator() returns a Fitness with evaluated == true; the error is worst_error when an output
// is not finite; evaluations() counts every call, the constant fitter's included. Not thread-safe (one
// evaluator per thread); the result depends only on the program, the dataset and the options.
#include <cstddef>
#include <memory>

#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/cost_model.hpp"
#include "pbrfit/gp/dataset.hpp"
#include "pbrfit/gp/error_measure.hpp"
#include "pbrfit/gp/fitness.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

enum class Precision { float32, float64 };

struct FitnessOptions {
  Precision precision = Precision::float32;
  ErrorOptions error;
  CostTable costs = gcn_cost_table();
};

class FitnessEvaluator {
 public:
  FitnessEvaluator(const Dataset& dataset, const FitnessOptions& options);
  ~FitnessEvaluator();
  FitnessEvaluator(const FitnessEvaluator&) = delete;
  FitnessEvaluator& operator=(const FitnessEvaluator&) = delete;

  Fitness operator()(const Program& program);
  // The error only (the constant fitter's objective); counted like operator().
  double error(const Program& program);
  std::size_t evaluations() const { return evaluations_; }
  const FitnessOptions& options() const { return options_; }

 private:
  FitnessOptions options_;
  std::unique_ptr<BatchInterpreter<float>> single_;
  std::unique_ptr<BatchInterpreter<double>> double_;
  std::size_t evaluations_ = 0;
};

}  // namespace pbrfit::gp
