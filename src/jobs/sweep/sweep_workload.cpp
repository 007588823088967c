#include "pbrfit/jobs/sweep/sweep_workload.hpp"

#include <stdexcept>

#include "pbrfit/core/error.hpp"
#include "pbrfit/sweep/hierarchy.hpp"

namespace pbrfit::jobs::sweep {
namespace {

using pbrfit::sweep::CellRef;

std::vector<pbrfit::sweep::LevelGrid> levels_of(const SweepSettings& s) {
  return pbrfit::sweep::hierarchy(s.axes, s.levels);
}

StartCode code_of(const pbrfit::sweep::CellFitResult& fit, const std::vector<StartCode>& source_codes) {
  if (fit.winner == pbrfit::sweep::Winner::global) return StartCode::global;
  if (fit.winner == pbrfit::sweep::Winner::default_start) return StartCode::default_start;
  return source_codes.at(fit.warm_index);
}

// The fitting problem with every evaluation checking for a stop, so a long fit gives up promptly.
template <class Task>
pbrfit::sweep::CellProblem cancellable(pbrfit::sweep::CellProblem problem, const Task& task) {
  problem.error = [error = std::move(problem.error), &task](std::span<const double> x, double tolerance) {
    if (task.stop_requested()) throw runtime::Cancelled();
    return error(x, tolerance);
  };
  return problem;
}

}  // namespace

SweepWorkload::SweepWorkload(SweepSettings settings)
    : settings_(std::move(settings)), schedule_(levels_of(settings_), settings_.marching) {
  const auto all = settings_.problem->models();
  for (std::size_t k = 0; k < settings_.models.size(); ++k) {
    models_.push_back(all.at(settings_.models[k]));
    models_.back().parameters = settings_.parameters.at(k);
    shapes_.push_back({models_.back().parameters.size(), models_.back().output_width()});
  }
  add_stage(runtime::stage<Nothing, WarmStarts, CellFits>("levels", schedule_.stage_count(), this)
                .items(&SweepWorkload::cell_count)
                .input(&SweepWorkload::warm_starts)
                .compute(&SweepWorkload::fit)
                .check(&SweepWorkload::check_cell)
                .blocks(&SweepWorkload::cell_blocks)
                .kept_through(&SweepWorkload::cell_kept_through)
                .fold(&SweepWorkload::fold_cell));
  add_stage(runtime::stage<Nothing, LastLevel, Projection>("projections", settings_.projections.empty() ? 0 : 1, this)
                .items(&SweepWorkload::projection_count)
                .input(&SweepWorkload::last_level)
                .compute(&SweepWorkload::project)
                .check(&SweepWorkload::check_projection)
                .blocks(&SweepWorkload::projection_blocks));
  render_plan_ = settings_.problem->render_plan(schedule_.levels().back());
  add_stage(runtime::stage<Nothing, RenderCells, RenderImage>("render", render_plan_ ? 1 : 0, this)
                .items(&SweepWorkload::render_count)
                .input(&SweepWorkload::render_cells)
                .compute(&SweepWorkload::render)
                .check(&SweepWorkload::check_render)
                .blocks(&SweepWorkload::render_blocks));
}

std::string SweepWorkload::group_name(std::size_t model, std::uint32_t level) const {
  return models_[model].name + "/level" + std::to_string(level);
}

SweepWorkload::WarmStarts SweepWorkload::warm_starts(std::uint32_t step, std::uint64_t item,
                                                     const runtime::KeptResults& kept) const {
  const CellRef cell = schedule_.cell_of(step, item);
  WarmStarts warm;
  for (const CellRef& source : schedule_.sources(cell)) {
    warm.codes.push_back(source.level == cell.level ? StartCode::neighbour : StartCode::parent);
    warm.fits.push_back(kept.at<CellFits>({schedule_.stage_of(source), schedule_.item_of(source)}));
  }
  return warm;
}

CellFits SweepWorkload::fit(const runtime::StageTask<Nothing, WarmStarts>& task) const {
  const CellRef cell = schedule_.cell_of(task.step(), task.item());
  const WarmStarts& sources = task.input;
  if (sources.codes.size() != sources.fits.size()) throw RunError("sweep: warm starts without their start codes");
  for (const auto& fits : sources.fits) require_shapes(fits, shapes_);
  const auto target = settings_.problem->target(schedule_.levels()[cell.level].coordinates(cell.cell));
  CellFits fits;
  for (std::size_t m = 0; m < models_.size(); ++m) {
    std::vector<pbrfit::sweep::WarmStart> warm;
    for (const auto& source : sources.fits) warm.push_back({source[m].parameters, source[m].error});
    const auto problem = cancellable(target->problem(settings_.models[m], models_[m].parameters), task);
    RandomStream random = task.random(m);
    const auto fit = pbrfit::sweep::fit_cell(problem, warm, settings_.fit, random);
    fits.push_back({fit.parameters, fit.error, fit.evaluations, code_of(fit, sources.codes), fit.global_ran,
                    target->outputs(settings_.models[m], fit.parameters)});
  }
  return fits;
}

void SweepWorkload::check_cell(const StageItem&, const CellFits& fits) const { require_shapes(fits, shapes_); }

std::vector<store::Block> SweepWorkload::cell_blocks(const StageItem& item, const CellFits& fits) const {
  const CellRef cell = schedule_.cell_of(item.step, item.item());
  const auto& grid = schedule_.levels()[cell.level];
  const auto at = grid.indices(cell.cell);
  const std::vector<std::uint64_t> offset(at.begin(), at.end()), ones(at.size(), 1);
  std::vector<store::Block> out;
  for (std::size_t m = 0; m < models_.size(); ++m) {
    const std::string group = group_name(m, cell.level);
    const auto scalar = [&](const std::string& table, store::Number value) {
      out.push_back({group, table, offset, ones, {value}});
    };
    const ModelFit& fit = fits[m];
    for (std::size_t k = 0; k < fit.parameters.size(); ++k) scalar(models_[m].parameters[k].name, fit.parameters[k]);
    scalar("error", fit.error);
    scalar("evaluations", fit.evaluations);
    scalar("start", static_cast<std::uint8_t>(fit.start));
    scalar("global_search", fit.global_ran ? 1u : 0u);
    std::size_t next = 0;
    for (const auto& output : models_[m].outputs) {
      const auto first = fit.outputs.begin() + std::ptrdiff_t(next);
      std::vector<store::Number> values(first, first + std::ptrdiff_t(output.components));
      next += output.components;
      if (output.components == 1) {
        out.push_back({group, output.name, offset, ones, std::move(values)});
        continue;
      }
      auto vector_offset = offset, vector_count = ones;
      vector_offset.push_back(0);
      vector_count.push_back(output.components);
      out.push_back({group, output.name, vector_offset, vector_count, std::move(values)});
    }
  }
  return out;
}

std::uint32_t SweepWorkload::cell_kept_through(const StageItem& item) const {
  const CellRef cell = schedule_.cell_of(item.step, item.item());
  if (cell.level == final_level()) {
    if (render_plan_) return first_stage("render");
    if (!settings_.projections.empty()) return first_stage("projections");
  }
  return schedule_.last_reader(cell);
}

}  // namespace pbrfit::jobs::sweep
