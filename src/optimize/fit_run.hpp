#pragma once
// One call of the default fitter (fit.hpp): the state that its warm-start polish and its rounds share.
//
// Invariants: every evaluation goes through evaluator_; best_ is the best candidate kept so far and
// result_ records where it came from.
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/candidate.hpp"
#include "pbrfit/optimize/evaluator.hpp"
#include "pbrfit/optimize/fit.hpp"

namespace pbrfit::optimize::detail {

class FitRun {
 public:
  FitRun(const Objective& objective, const Bounds& bounds, const FitOptions& options, RandomStream& random);

  FitResult run(std::span<const std::vector<double>> warm_starts);

 private:
  void polish_warm_starts(std::span<const std::vector<double>> warm_starts);
  StopReason rounds(std::span<const std::vector<double>> warm_starts);
  bool round(std::span<const std::vector<double>> seeds);
  bool keep_if_better(const Candidate& candidate, FitPhase phase);
  std::size_t polish_budget() const;
  std::size_t population_for(std::size_t global_budget) const;

  Evaluator evaluator_;
  const Bounds& bounds_;
  const FitOptions& options_;
  RandomStream& random_;
  DeOptions global_;
  NelderMeadOptions polish_;
  Candidate best_;
  FitResult result_;
};

}  // namespace pbrfit::optimize::detail
