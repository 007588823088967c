#include "pbrfit/optimize/stop_reason.hpp"

namespace pbrfit::optimize {

const char* to_string(StopReason reason) {
  switch (reason) {
    case StopReason::budget:
      return "budget";
    case StopReason::iteration_limit:
      return "iteration limit";
    case StopReason::target:
      return "target reached";
    case StopReason::stagnation:
      return "stagnation";
    case StopReason::spread:
      return "population spread";
    case StopReason::converged:
      return "converged";
  }
  return "";
}

}  // namespace pbrfit::optimize
