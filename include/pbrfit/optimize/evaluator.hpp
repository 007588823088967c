#pragma once
// The only way an optimizer calls its objective: counts every evaluation, enforces the evaluation budget
// and holds the current tolerance of the schedule. Optimizers that run one after another on the same
// problem share one evaluator, so the budget is a hard cap across all of them.
//
// Invariants:
//  - used() <= max_evaluations() always; evaluating when exhausted() throws std::logic_error;
//  - with a non-constant schedule one evaluation is held back from every phase so that finalize() can
//    always re-measure the reported best at the final tolerance (a budget of one evaluation instead
//    runs at the final tolerance from the start);
//  - tolerance() never grows; it starts at schedule.start (the constructor throws std::invalid_argument
//    unless 0 <= schedule.final <= schedule.start);
//  - a NaN from the objective is returned (and counted) as +inf.
#include <cstddef>
#include <span>

#include "pbrfit/optimize/candidate.hpp"
#include "pbrfit/optimize/objective.hpp"
#include "pbrfit/optimize/tolerance_schedule.hpp"

namespace pbrfit::optimize {

class Evaluator {
 public:
  Evaluator(Objective objective, std::size_t max_evaluations, ToleranceSchedule schedule = {});

  // The objective at x and the current tolerance. A named function rather than operator(), so that an
  // evaluator never converts to an Objective by accident.
  double measure(std::span<const double> x);
  // Measures out.x into out.value and out.tolerance.
  void measure(Candidate& out);

  bool exhausted() const { return used_ >= usable(); }
  std::size_t used() const { return used_; }
  std::size_t remaining() const { return exhausted() ? 0 : usable() - used_; }
  std::size_t max_evaluations() const { return max_evaluations_; }

  // Caps the phase that follows: exhausted() once used() reaches `used_limit` (never beyond the budget).
  void limit_to(std::size_t used_limit) { phase_limit_ = used_limit; }
  void lift_limit() { phase_limit_ = max_evaluations_; }

  const ToleranceSchedule& schedule() const { return schedule_; }
  double tolerance() const { return tolerance_; }
  bool at_final_tolerance() const { return tolerance_ == schedule_.final; }
  // Tightens to schedule().at(relative_scale) if that is tighter; true when the tolerance changed.
  bool follow_scale(double relative_scale);
  // Tightens to the final tolerance; true when the tolerance changed.
  bool use_final_tolerance();
  // Makes `best` a value at the final tolerance, re-evaluating it (with the held-back evaluation) if its
  // value was computed at another tolerance. Does nothing for a candidate without a point.
  void finalize(Candidate& best);

 private:
  std::size_t usable() const;
  double call(std::span<const double> x);

  Objective objective_;
  std::size_t max_evaluations_;
  std::size_t phase_limit_;
  std::size_t used_ = 0;
  ToleranceSchedule schedule_;
  double tolerance_;
};

}  // namespace pbrfit::optimize
