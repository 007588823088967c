#include "pbrfit/jobs/sweep/sweep_problem.hpp"

#include "pbrfit/core/error.hpp"

namespace pbrfit::jobs::sweep {

std::size_t ModelInfo::output_width() const {
  std::size_t width = 0;
  for (const auto& output : outputs) width += output.components;
  return width;
}

std::vector<double> SweepProblem::render(std::size_t, const RenderPlan&, std::size_t, std::size_t, std::size_t,
                                         std::span<const std::vector<double>>) const {
  throw RunError("sweep: problem '" + description() + "' has no check render");
}

}  // namespace pbrfit::jobs::sweep
