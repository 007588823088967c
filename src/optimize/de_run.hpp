#pragma once
// One Differential Evolution run (differential_evolution.hpp): the population, the trials of the current
// generation and the stopping state.
//
// Invariants: population_ and trials_ have the same size; every evaluation goes through evaluator_;
// generations_ counts completed generations only.
#include <cstddef>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/differential_evolution.hpp"
#include "population.hpp"
#include "stagnation_monitor.hpp"
#include "trial_control.hpp"

namespace pbrfit::optimize::detail {

class DeRun {
 public:
  DeRun(Evaluator& evaluator, const Bounds& bounds, const DeOptions& options, RandomStream& random);

  DeResult run(std::span<const std::vector<double>> seeds);

 private:
  void initialize(std::span<const std::vector<double>> seeds);
  bool stop_before_generation(StopReason& reason);
  bool stagnated() const;
  void generation();
  void evaluate_member(Population& members, std::size_t i);
  DeResult result(StopReason reason) const;

  Evaluator& evaluator_;
  const Bounds& bounds_;
  const DeOptions& options_;
  RandomStream& random_;
  std::vector<std::size_t> free_;
  std::size_t size_;
  Population population_;
  Population trials_;
  std::vector<std::size_t> ranking_;  // of population_, refreshed every generation
  TrialControlSource controls_;
  StagnationMonitor stagnation_;
  std::size_t first_evaluation_;
  std::size_t generations_ = 0;
};

}  // namespace pbrfit::optimize::detail
