#pragma once
// A validated `sweep` job: the problem, the models to fit (with the job's parameter bounds), the finest
// grid, the hierarchy and marching order, and the cell fitter's options.
//
// Invariants (sweep_kind.cpp establishes them from the job file): models is non-empty and each index is
// a model of the problem; parameters[k] has the parameters of models[k] in the problem's order; axes
// are the problem's axes in its order; levels is between 1 and sweep::max_level_count(axes).
#include <memory>
#include <optional>
#include <vector>

#include "pbrfit/jobs/sweep/sweep_problem.hpp"
#include "pbrfit/sweep/cell_fit.hpp"
#include "pbrfit/sweep/sweep_schedule.hpp"

namespace pbrfit::jobs::sweep {

struct SweepSettings {
  std::shared_ptr<const SweepProblem> problem;
  std::vector<std::size_t> models;
  std::vector<std::vector<optimize::Parameter>> parameters;
  std::vector<pbrfit::sweep::GridAxis> axes;
  std::size_t levels = 1;
  std::optional<pbrfit::sweep::Marching> marching;
  std::vector<std::size_t> projections;  // axes the finest level's fits are averaged over (a last stage)
  pbrfit::sweep::CellFitOptions fit;
};

}  // namespace pbrfit::jobs::sweep
