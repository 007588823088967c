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
pbrfit::sweep::CellProblem cancellable(pbrfit::sweep::CellProblem problem, const runtime::ItemTask& task) {
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
}

std::string SweepWorkload::group_name(std::size_t model, std::uint32_t level) const {
  return models_[model].name + "/level" + std::to_string(level);
}

std::uint32_t SweepWorkload::stage_count() const {
  return schedule_.stage_count() + (settings_.projections.empty() ? 0 : 1);
}

std::uint64_t SweepWorkload::item_count(std::uint32_t stage) const {
  return is_projection(stage) ? settings_.projections.size() : schedule_.stages()[stage].cells.size();
}

Bytes SweepWorkload::item_input(std::uint32_t stage, std::uint64_t item, const ItemResults& kept) const {
  if (is_projection(stage)) return projection_input(kept);
  const CellRef cell = schedule_.cell_of(stage, item);
  const auto sources = schedule_.sources(cell);
  ByteWriter out;
  out.put_varint(sources.size());
  for (const CellRef& source : sources) {
    const auto found = kept.find({schedule_.stage_of(source), schedule_.item_of(source)});
    if (found == kept.end()) throw std::logic_error("sweep: a warm start's fit was not kept");
    out.put(static_cast<std::uint8_t>(source.level == cell.level ? StartCode::neighbour : StartCode::parent));
    out.put_bytes(found->second);
  }
  return out.take();
}

Bytes SweepWorkload::compute(const runtime::ItemTask& task) const {
  if (is_projection(task.id.stage)) return project(task);
  const CellRef cell = schedule_.cell_of(task.id.stage, task.id.item);
  ByteReader input(task.input);
  std::vector<StartCode> codes;
  std::vector<std::vector<ModelFit>> sources;
  for (std::uint64_t n = input.get_varint(); n-- > 0;) {
    codes.push_back(static_cast<StartCode>(input.get<std::uint8_t>()));
    sources.push_back(decode_cell(input.get_bytes(), shapes_));
  }
  const auto target = settings_.problem->target(schedule_.levels()[cell.level].coordinates(cell.cell));
  std::vector<ModelFit> fits;
  for (std::size_t m = 0; m < models_.size(); ++m) {
    std::vector<pbrfit::sweep::WarmStart> warm;
    for (const auto& source : sources) warm.push_back({source[m].parameters, source[m].error});
    const auto problem = cancellable(target->problem(settings_.models[m], models_[m].parameters), task);
    RandomStream random = task.random(m);
    const auto fit = pbrfit::sweep::fit_cell(problem, warm, settings_.fit, random);
    fits.push_back({fit.parameters, fit.error, fit.evaluations, code_of(fit, codes), fit.global_ran,
                    target->outputs(settings_.models[m], fit.parameters)});
  }
  return encode_cell(fits);
}

std::vector<store::Block> SweepWorkload::blocks(WorkItemId id, const Bytes& result) const {
  if (is_projection(id.stage)) return projection_blocks(id, result);
  const CellRef cell = schedule_.cell_of(id.stage, id.item);
  const auto& grid = schedule_.levels()[cell.level];
  const auto at = grid.indices(cell.cell);
  const std::vector<std::uint64_t> offset(at.begin(), at.end()), ones(at.size(), 1);
  const auto fits = decode_cell(result, shapes_);
  std::vector<store::Block> out;
  for (std::size_t m = 0; m < models_.size(); ++m) {
    const std::string group = group_name(m, cell.level);
    const auto scalar = [&](const std::string& table, double value) {
      out.push_back({group, table, offset, ones, {value}});
    };
    const ModelFit& fit = fits[m];
    for (std::size_t k = 0; k < fit.parameters.size(); ++k) scalar(models_[m].parameters[k].name, fit.parameters[k]);
    scalar("error", fit.error);
    scalar("evaluations", double(fit.evaluations));
    scalar("start", double(static_cast<std::uint8_t>(fit.start)));
    scalar("global_search", fit.global_ran ? 1.0 : 0.0);
    std::size_t next = 0;
    for (const auto& output : models_[m].outputs) {
      const auto first = fit.outputs.begin() + std::ptrdiff_t(next);
      std::vector<double> values(first, first + std::ptrdiff_t(output.components));
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

std::uint32_t SweepWorkload::kept_through(WorkItemId id) const {
  if (is_projection(id.stage)) return id.stage;
  const CellRef cell = schedule_.cell_of(id.stage, id.item);
  if (!settings_.projections.empty() && cell.level == final_level()) return schedule_.stage_count();
  return schedule_.last_reader(cell);
}

}  // namespace pbrfit::jobs::sweep
