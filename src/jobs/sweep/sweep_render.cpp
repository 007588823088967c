// The check render of a sweep (sweep_workload.hpp): the finished table shaded into images of the problem's
// scene, beside ground truth.
#include <algorithm>

#include "pbrfit/core/error.hpp"
#include "pbrfit/jobs/sweep/sweep_workload.hpp"

namespace pbrfit::jobs::sweep {
namespace {

std::vector<double> pixel_positions(std::size_t count) {
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = double(i);
  return values;
}

// A work item of the render: a band of rows of one model's image.
struct RenderItem {
  std::size_t model, image, first_row, rows;
};

std::size_t band_count(const RenderPlan& plan) { return (plan.resolution + plan.band_rows - 1) / plan.band_rows; }

RenderItem render_item(const RenderPlan& plan, std::uint64_t item) {
  const std::size_t bands = band_count(plan), images = plan.image_values.size();
  const std::size_t band = item % bands, image = (item / bands) % images, model = item / (bands * images);
  const std::size_t first = band * plan.band_rows;
  return {model, image, first, std::min(plan.band_rows, plan.resolution - first)};
}

}  // namespace

std::uint64_t SweepWorkload::render_count(std::uint32_t) const {
  return render_plan_ ? models_.size() * render_plan_->image_values.size() * band_count(*render_plan_) : 0;
}

SweepWorkload::RenderCells SweepWorkload::render_cells(std::uint32_t, std::uint64_t item,
                                                       const runtime::KeptResults& kept) const {
  RenderCells fits;
  for (std::size_t c : render_plan_->cells.at(render_item(*render_plan_, item).image)) {
    const pbrfit::sweep::CellRef cell{final_level(), c};
    fits.push_back(kept.at<CellFits>({schedule_.stage_of(cell), schedule_.item_of(cell)}));
  }
  return fits;
}

SweepWorkload::RenderImage SweepWorkload::render(const runtime::StageTask<Nothing, RenderCells>& task) const {
  const RenderItem at = render_item(*render_plan_, task.item());
  std::vector<std::vector<double>> outputs;
  for (const CellFits& fits : task.input) {
    require_shapes(fits, shapes_);
    outputs.push_back(fits[at.model].outputs);
  }
  if (task.stop_requested()) throw runtime::Cancelled();
  return settings_.problem->render(settings_.models[at.model], *render_plan_, at.image, at.first_row, at.rows, outputs);
}

void SweepWorkload::check_render(const StageItem& item, const RenderImage& image) const {
  const RenderItem at = render_item(*render_plan_, item.item());
  const std::size_t curves = at.first_row == 0 && render_plan_->curves ? render_plan_->curves->size() : 0;
  if (image.size() != render_plan_->layers.size() * at.rows * render_plan_->resolution + curves)
    throw RunError("a sweep's render has the wrong size");
}

std::vector<store::Block> SweepWorkload::render_blocks(const StageItem& at, const RenderImage& image) const {
  const RenderItem item = render_item(*render_plan_, at.item());
  const std::size_t n = render_plan_->resolution, size = item.rows * n;
  std::vector<store::Block> out;
  for (std::size_t layer = 0; layer < render_plan_->layers.size(); ++layer)
    out.push_back({models_[item.model].name + "/render", render_plan_->layers[layer].name,
                   {item.image, item.first_row, 0}, {1, item.rows, n},
                   store::reals(std::span<const double>(image).subspan(layer * size, size))});
  if (item.first_row == 0 && render_plan_->curves) {
    const RenderCurves& curves = *render_plan_->curves;
    const std::size_t sets = curves.sets.size(), positions = curves.positions.size(), curve = sets * positions;
    const std::size_t first = render_plan_->layers.size() * size;
    for (std::size_t layer = 0; layer < curves.layers.size(); ++layer)
      out.push_back({models_[item.model].name + "/" + curves.group, curves.layers[layer].name,
                     {item.image, 0, 0}, {1, sets, positions},
                     store::reals(std::span<const double>(image).subspan(first + layer * curve, curve))});
  }
  return out;
}

store::Group SweepWorkload::curves_group(std::size_t m) const {
  const RenderPlan& plan = *render_plan_;
  const RenderCurves& curves = *plan.curves;
  store::Group g;
  g.name = models_[m].name + "/" + curves.group;
  g.description = curves.description;
  g.attributes = {{"model", models_[m].name}};
  g.axes.push_back({plan.image_axis, plan.image_values, plan.image_axis_description});
  g.axes.push_back({curves.set_axis, curves.sets, curves.set_description});
  g.axes.push_back({curves.position_axis, curves.positions, curves.position_description});
  for (const auto& layer : curves.layers) {
    store::Table t{layer.name, {plan.image_axis, curves.set_axis, curves.position_axis}, layer.description};
    t.attributes = {{"role", "output"}};
    g.tables.push_back(t);
  }
  return g;
}

store::Group SweepWorkload::render_group(std::size_t m) const {
  const RenderPlan& plan = *render_plan_;
  store::Group g;
  g.name = models_[m].name + "/render";
  g.description = "the check render of " + models_[m].name + "'s table: " + plan.description;
  g.attributes = {{"model", models_[m].name}, {"resolution", std::to_string(plan.resolution)}};
  g.axes.push_back({plan.image_axis, plan.image_values, plan.image_axis_description});
  g.axes.push_back({"row", pixel_positions(plan.resolution), "pixel row, 0 at the top"});
  g.axes.push_back({"column", pixel_positions(plan.resolution), "pixel column, 0 at the left"});
  for (const auto& layer : plan.layers) {
    store::Table t{layer.name, {plan.image_axis, "row", "column"}, layer.description};
    t.attributes = {{"role", "output"}};
    g.tables.push_back(t);
  }
  return g;
}

}  // namespace pbrfit::jobs::sweep
