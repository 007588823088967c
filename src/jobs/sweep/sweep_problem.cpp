#include "pbrfit/jobs/sweep/sweep_problem.hpp"

namespace pbrfit::jobs::sweep {

std::size_t ModelInfo::output_width() const {
  std::size_t width = 0;
  for (const auto& output : outputs) width += output.components;
  return width;
}

}  // namespace pbrfit::jobs::sweep
