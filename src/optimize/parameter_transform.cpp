#include "pbrfit/optimize/parameter_transform.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pbrfit::optimize {

std::string invalid_reason(const Parameter& parameter) {
  const double lower = parameter.lower;
  const double upper = parameter.upper;
  if (!std::isfinite(lower) || !std::isfinite(upper) || lower > upper)
    return "parameter '" + parameter.name + "' needs finite bounds, lower <= upper";
  if (parameter.transform == Transform::log && !(lower > 0.0))
    return "log parameter '" + parameter.name + "' needs lower > 0";
  if (parameter.transform == Transform::cosine && (lower < 0.0 || upper > std::numbers::pi))
    return "angle parameter '" + parameter.name + "' must lie in [0, pi]";
  return "";
}

void validate(const Parameter& parameter) {
  if (const std::string reason = invalid_reason(parameter); !reason.empty())
    throw std::invalid_argument("optimize: " + reason);
}

double to_internal(const Parameter& parameter, double value) {
  const double lower = parameter.lower;
  const double upper = parameter.upper;
  if (lower == upper || !(value > lower)) return 0.0;  // NaN too
  if (value >= upper) return 1.0;
  switch (parameter.transform) {
    case Transform::linear:
      return (value - lower) / (upper - lower);
    case Transform::log:
      return std::log(value / lower) / std::log(upper / lower);
    case Transform::cosine:
      return (std::cos(lower) - std::cos(value)) / (std::cos(lower) - std::cos(upper));
  }
  return 0.0;
}

double from_internal(const Parameter& parameter, double internal) {
  const double lower = parameter.lower;
  const double upper = parameter.upper;
  const double u = std::clamp(internal, 0.0, 1.0);
  double value = lower;
  switch (parameter.transform) {
    case Transform::linear:
      value = lower + u * (upper - lower);
      break;
    case Transform::log:
      value = lower * std::exp(u * std::log(upper / lower));
      break;
    case Transform::cosine:
      value = std::acos(std::cos(lower) - u * (std::cos(lower) - std::cos(upper)));
      break;
  }
  return std::clamp(value, lower, upper);
}

}  // namespace pbrfit::optimize
