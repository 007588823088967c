#pragma once
// The check render of LTC tables (ltc_problem.hpp, "Check render"): which images a table's render has and
// what each of their pixels holds.
#include <optional>
#include <span>
#include <vector>

#include "pbrfit/jobs/sweep/ltc_problem.hpp"

namespace pbrfit::jobs::sweep {

// Images of the last level `grid` (view axis `view`, roughness axis `roughness` if any); none when
// render_size is 0.
std::optional<RenderPlan> ltc_render_plan(const LtcProblemSettings& settings, const pbrfit::sweep::LevelGrid& grid,
                                          std::size_t view, std::optional<std::size_t> roughness);

// Rows [first_row, first_row + rows) of image `image` of the model `spec`, whose outputs are laid out as
// `outputs`, from its outputs at the image's cells.
std::vector<double> ltc_render(const LtcModelSpec& spec, const std::vector<ModelOutput>& outputs,
                               const RenderPlan& plan, std::size_t image, std::size_t first_row, std::size_t rows,
                               std::size_t view, std::span<const std::vector<double>> values);

}  // namespace pbrfit::jobs::sweep
