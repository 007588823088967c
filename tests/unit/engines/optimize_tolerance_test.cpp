#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "pbrfit/optimize/evaluator.hpp"
#include "pbrfit/optimize/tolerance_schedule.hpp"

using namespace pbrfit::optimize;

TEST_CASE("A tolerance schedule steps from start to final as the search narrows", "[optimize]") {
  const ToleranceSchedule schedule{1e-2, 1e-8, 1e-4, 4};  // levels 1e-2, 1e-4, 1e-6, 1e-8
  CHECK(schedule.at(2.0) == 1e-2);
  CHECK(schedule.at(1.0) == 1e-2);
  CHECK(schedule.at(0.5) == 1e-2);
  CHECK(std::abs(schedule.at(1e-2) / 1e-4 - 1.0) < 1e-12);  // half way in log(scale): level 1 of 3
  CHECK(schedule.at(1e-4) == 1e-8);
  CHECK(schedule.at(0.0) == 1e-8);
  double previous = schedule.at(1.0);
  for (double scale = 1.0; scale > 1e-6; scale *= 0.9) {
    const double tolerance = schedule.at(scale);
    CHECK(tolerance <= previous);
    previous = tolerance;
  }
  CHECK(ToleranceSchedule::constant(1e-5).at(1e-9) == 1e-5);
  CHECK(ToleranceSchedule::constant(1e-5).is_constant());
}

TEST_CASE("The evaluator counts, caps and never loosens the tolerance", "[optimize]") {
  std::vector<double> seen_tolerances;
  const Objective objective = [&](std::span<const double> x, double tolerance) {
    seen_tolerances.push_back(tolerance);
    return x[0] + tolerance;
  };
  const std::vector<double> x{1.0};

  SECTION("constant schedule: the whole budget is usable") {
    Evaluator evaluator(objective, 3);
    CHECK(evaluator.remaining() == 3);
    for (int i = 0; i < 3; ++i) evaluator.measure(x);
    CHECK(evaluator.exhausted());
    CHECK(evaluator.used() == 3);
    CHECK_THROWS_AS(evaluator.measure(x), std::logic_error);
    CHECK(evaluator.used() == 3);
  }
  SECTION("non-constant schedule: one evaluation is held back for the final re-measurement") {
    Evaluator evaluator(objective, 3, ToleranceSchedule{1e-2, 1e-6, 1e-3, 2});
    CHECK(evaluator.remaining() == 2);
    Candidate best{x, 0.0, 0.0};
    evaluator.measure(best);
    evaluator.measure(x);
    CHECK(evaluator.exhausted());
    CHECK(best.tolerance == 1e-2);
    evaluator.finalize(best);
    CHECK(evaluator.used() == 3);
    CHECK(best.tolerance == 1e-6);
    CHECK(best.value == 1.0 + 1e-6);
    CHECK(seen_tolerances == std::vector<double>{1e-2, 1e-2, 1e-6});
  }
  SECTION("follow_scale only tightens") {
    Evaluator evaluator(objective, 10, ToleranceSchedule{1e-2, 1e-6, 1e-4, 3});
    CHECK(evaluator.tolerance() == 1e-2);
    CHECK(evaluator.follow_scale(1e-3));
    const double tightened = evaluator.tolerance();
    CHECK(tightened < 1e-2);
    CHECK_FALSE(evaluator.follow_scale(1.0));
    CHECK(evaluator.tolerance() == tightened);
    CHECK(evaluator.use_final_tolerance());
    CHECK(evaluator.at_final_tolerance());
    CHECK_FALSE(evaluator.use_final_tolerance());
  }
  SECTION("a phase limit caps the evaluations until it is lifted") {
    Evaluator evaluator(objective, 10);
    evaluator.limit_to(4);
    for (int i = 0; i < 4; ++i) evaluator.measure(x);
    CHECK(evaluator.exhausted());
    evaluator.lift_limit();
    CHECK(evaluator.remaining() == 6);
  }
  SECTION("NaN counts as +inf") {
    Evaluator evaluator([](std::span<const double>) { return std::nan(""); }, 1);
    CHECK(evaluator.measure(x) == std::numeric_limits<double>::infinity());
  }
}
