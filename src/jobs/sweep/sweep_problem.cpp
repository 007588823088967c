#include "pbrfit/jobs/sweep/sweep_problem.hpp"

#include <stdexcept>

#include "pbrfit/core/error.hpp"

namespace pbrfit::jobs::sweep {

std::size_t ModelInfo::output_width() const {
  std::size_t width = 0;
  for (const auto& output : outputs) width += output.components;
  return width;
}

std::optional<std::size_t> ModelInfo::headline_offset() const {
  if (headline_output.empty()) return std::nullopt;
  std::size_t offset = 0;
  for (const auto& output : outputs) {
    if (output.name == headline_output && output.components == 1) return offset;
    offset += output.components;
  }
  throw std::logic_error("sweep: model '" + name + "' summarizes '" + headline_output + "', not a scalar output of it");
}

std::vector<double> SweepProblem::render(std::size_t, const RenderPlan&, std::size_t, std::size_t, std::size_t,
                                         std::span<const std::vector<double>>) const {
  throw RunError("sweep: problem '" + description() + "' has no check render");
}

}  // namespace pbrfit::jobs::sweep
