#include "pbrfit/gp/error_measure.hpp"

namespace pbrfit::gp {

std::string_view name(ErrorMeasure measure) {
  switch (measure) {
    case ErrorMeasure::rmse:
      return "rmse";
    case ErrorMeasure::max_abs:
      return "max_abs";
    case ErrorMeasure::relative:
      return "relative";
  }
  return "rmse";
}

std::optional<ErrorMeasure> error_measure_named(std::string_view text) {
  for (ErrorMeasure measure : {ErrorMeasure::rmse, ErrorMeasure::max_abs, ErrorMeasure::relative}) {
    if (name(measure) == text) return measure;
  }
  return std::nullopt;
}

}  // namespace pbrfit::gp
