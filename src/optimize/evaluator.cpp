#include "pbrfit/optimize/evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace pbrfit::optimize {

Evaluator::Evaluator(Objective objective, std::size_t max_evaluations, ToleranceSchedule schedule)
    : objective_(std::move(objective)),
      max_evaluations_(max_evaluations),
      phase_limit_(max_evaluations),
      schedule_(schedule),
      tolerance_(max_evaluations > 1 ? schedule.start : schedule.final) {
  if (!(schedule.final >= 0.0 && schedule.final <= schedule.start)) {
    throw std::invalid_argument("optimize: a tolerance schedule needs 0 <= final <= start");
  }
}

std::size_t Evaluator::usable() const {
  const std::size_t held_back = schedule_.is_constant() || max_evaluations_ <= 1 ? 0 : 1;
  const std::size_t budget = max_evaluations_ > held_back ? max_evaluations_ - held_back : 0;
  return std::min(phase_limit_, budget);
}

double Evaluator::call(std::span<const double> x) {
  if (used_ >= max_evaluations_) throw std::logic_error("optimize: objective evaluated beyond its budget");
  ++used_;
  const double value = objective_(x, tolerance_);
  return std::isnan(value) ? std::numeric_limits<double>::infinity() : value;
}

double Evaluator::measure(std::span<const double> x) {
  if (exhausted()) throw std::logic_error("optimize: objective evaluated beyond its budget");
  return call(x);
}

void Evaluator::measure(Candidate& out) {
  out.value = measure(out.x);
  out.tolerance = tolerance_;
}

bool Evaluator::follow_scale(double relative_scale) {
  const double scheduled = schedule_.at(relative_scale);
  if (!(scheduled < tolerance_)) return false;
  tolerance_ = scheduled;
  return true;
}

bool Evaluator::use_final_tolerance() {
  if (!(schedule_.final < tolerance_)) return false;
  tolerance_ = schedule_.final;
  return true;
}

void Evaluator::finalize(Candidate& best) {
  use_final_tolerance();
  if (best.x.empty() || best.tolerance == tolerance_ || used_ >= max_evaluations_) return;
  best.value = call(best.x);
  best.tolerance = tolerance_;
}

}  // namespace pbrfit::optimize
