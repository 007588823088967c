#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "pbrfit/optimize/parameter_space.hpp"

using namespace pbrfit::optimize;

namespace {

const Parameter scale{"scale", 1e-3, 1e3, Transform::log};
const Parameter angle{"theta", 0.1, 1.4, Transform::cosine};
const Parameter offset{"offset", -2.0, 6.0, Transform::linear};

}  // namespace

TEST_CASE("Transforms map the bounds onto [0, 1] and round-trip", "[optimize]") {
  for (const Parameter& parameter : {scale, angle, offset}) {
    CAPTURE(parameter.name);
    CHECK(to_internal(parameter, parameter.lower) == 0.0);
    CHECK(std::abs(to_internal(parameter, parameter.upper) - 1.0) < 1e-15);
    CHECK(from_internal(parameter, 0.0) == parameter.lower);
    CHECK(std::abs(from_internal(parameter, 1.0) - parameter.upper) <= 1e-13 * parameter.upper);
    double previous = -std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 100; ++k) {
      const double u = k / 100.0;
      const double value = from_internal(parameter, u);
      CHECK(value >= parameter.lower);
      CHECK(value <= parameter.upper);
      CHECK(std::abs(to_internal(parameter, value) - u) < 1e-12);
      CHECK(value > previous);  // increasing
      previous = value;
    }
  }
}

TEST_CASE("Each transform spaces values the way section 7.6 asks", "[optimize]") {
  CHECK(std::abs(from_internal(scale, 0.5) - 1.0) < 1e-12);  // geometric midpoint of [1e-3, 1e3]
  CHECK(std::abs(from_internal(offset, 0.25) - 0.0) < 1e-15);
  const double mid_cos = 0.5 * (std::cos(angle.lower) + std::cos(angle.upper));
  CHECK(std::abs(std::cos(from_internal(angle, 0.5)) - mid_cos) < 1e-12);  // uniform in cos(theta)
}

TEST_CASE("Out-of-range values are clamped, invalid parameters rejected", "[optimize]") {
  CHECK(to_internal(scale, -5.0) == 0.0);
  CHECK(to_internal(scale, 1e9) == 1.0);
  CHECK(to_internal(offset, std::nan("")) == 0.0);
  CHECK(from_internal(offset, 7.0) == offset.upper);
  CHECK(from_internal(offset, -7.0) == offset.lower);
  CHECK_THROWS_AS(validate(Parameter{"bad", 0.0, 1.0, Transform::log}), std::invalid_argument);
  CHECK_THROWS_AS(validate(Parameter{"bad", 0.0, 4.0, Transform::cosine}), std::invalid_argument);
  CHECK_THROWS_AS(validate(Parameter{"bad", 2.0, 1.0, Transform::linear}), std::invalid_argument);
  const double infinity = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(validate(Parameter{"bad", 0.0, infinity, Transform::linear}), std::invalid_argument);
  CHECK(invalid_reason(Parameter{"k", 0.0, 1.0, Transform::log}) == "log parameter 'k' needs lower > 0");
  CHECK(invalid_reason(scale).empty());
}

TEST_CASE("A parameter space converts whole vectors and wraps objectives", "[optimize]") {
  ParameterSpace space({scale, angle, offset});
  space.add(Parameter{"fixed", 3.0, 3.0, Transform::linear});
  CHECK(space.size() == 4);
  CHECK(space.index_of("theta") == 1);
  CHECK_THROWS_AS(space.index_of("nope"), std::out_of_range);
  CHECK_THROWS_AS(space.add(offset), std::invalid_argument);

  const Bounds internal = space.internal_bounds();
  CHECK(internal.lower == std::vector<double>{0.0, 0.0, 0.0, 0.0});
  CHECK(internal.upper == std::vector<double>{1.0, 1.0, 1.0, 0.0});
  CHECK(space.model_bounds().upper == std::vector<double>{1e3, 1.4, 6.0, 3.0});

  const std::vector<double> model{10.0, 0.7, 1.5, 3.0};
  const std::vector<double> round_trip = space.from_internal(space.to_internal(model));
  for (std::size_t i = 0; i < model.size(); ++i) CHECK(std::abs(round_trip[i] - model[i]) < 1e-12 * (1 + model[i]));

  std::vector<double> seen;
  double seen_tolerance = 0.0;
  const Objective wrapped = space.internal_objective([&](std::span<const double> p, double tolerance) {
    seen.assign(p.begin(), p.end());
    seen_tolerance = tolerance;
    return p[0];
  });
  const std::vector<double> u{0.5, 0.0, 1.0, 0.0};
  CHECK(std::abs(wrapped(u, 1e-4) - 1.0) < 1e-12);
  CHECK(seen == space.from_internal(u));
  CHECK(seen_tolerance == 1e-4);
}
