#include "pbrfit/optimize/tolerance_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace pbrfit::optimize {

double ToleranceSchedule::at(double relative_scale) const {
  if (is_constant() || relative_scale >= 1.0) return start;
  if (!(relative_scale > final_scale)) return final;  // also a NaN or zero scale
  const int steps = std::max(levels, 2) - 1;
  const double progress = std::log(relative_scale) / std::log(final_scale);  // in (0, 1)
  const int level = std::min(static_cast<int>(progress * steps), steps);
  if (level == steps) return final;
  return start * std::pow(final / start, static_cast<double>(level) / steps);
}

}  // namespace pbrfit::optimize
