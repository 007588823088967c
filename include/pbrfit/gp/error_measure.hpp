#pragma once
// How far a program's outputs are from the target, accumulated in double whatever the evaluation type:
//  - rmse: sqrt(sum w r^2 / sum w), r = output - target (the default);
//  - max_abs: max |r| over rows with weight > 0;
//  - relative: sqrt(sum w (r / max(|target|, relative_floor))^2 / sum w).
// An output that is not finite at any row with weight > 0 makes the error +inf (the worst).
#include <cstddef>
#include <limits>
#include <optional>
#include <string_view>

namespace pbrfit::gp {

enum class ErrorMeasure { rmse, max_abs, relative };

struct ErrorOptions {
  ErrorMeasure measure = ErrorMeasure::rmse;
  double relative_floor = 1e-6;  // the smallest |target| a relative error divides by
};

std::string_view name(ErrorMeasure measure);  // "rmse", "max_abs", "relative"
std::optional<ErrorMeasure> error_measure_named(std::string_view text);

inline constexpr double worst_error = std::numeric_limits<double>::infinity();

}  // namespace pbrfit::gp
