// The projections of a sweep (sweep_workload.hpp): the last level's fits averaged over an axis.
#include <cmath>

#include "pbrfit/core/error.hpp"
#include "pbrfit/jobs/sweep/sweep_workload.hpp"

namespace pbrfit::jobs::sweep {
namespace {

// Mean and standard deviation of a running set of values (Welford), order fixed by the caller.
struct Moments {
  double count = 0.0, mean = 0.0, square_sum = 0.0;
  void add(double x) {
    count += 1.0;
    const double delta = x - mean;
    mean += delta / count;
    square_sum += delta * (x - mean);
  }
  double deviation() const { return count > 1.0 ? std::sqrt(square_sum / (count - 1.0)) : 0.0; }
};

}  // namespace

std::string SweepWorkload::projection_name(std::size_t model, std::size_t projection) const {
  const auto& axis = schedule_.levels().back().axes()[settings_.projections[projection]];
  return group_name(model, final_level()) + "_mean_over_" + axis.name;
}

pbrfit::sweep::LevelGrid SweepWorkload::projected_grid(std::size_t projection) const {
  std::vector<pbrfit::sweep::GridAxis> axes;
  const auto& all = schedule_.levels().back().axes();
  for (std::size_t d = 0; d < all.size(); ++d)
    if (d != settings_.projections[projection]) axes.push_back(all[d]);
  return pbrfit::sweep::LevelGrid(std::move(axes));
}

store::Group SweepWorkload::projection_group(std::size_t m, std::size_t p) const {
  const auto grid = projected_grid(p);
  const std::string over = schedule_.levels().back().axes()[settings_.projections[p]].name;
  store::Group g;
  g.name = projection_name(m, p);
  g.description = models_[m].description + "; the last level's fits averaged over " + over;
  g.attributes = {{"model", models_[m].name}, {"projected_over", over}};
  std::vector<std::string> names;
  for (const auto& axis : grid.axes()) {
    g.axes.push_back({axis.name, axis.values(), "as in " + group_name(m, final_level())});
    names.push_back(axis.name);
  }
  const auto add = [&](const std::string& name, const std::string& what, const char* role) {
    store::Table mean{name, names, "mean over " + over + " of " + what};
    mean.attributes = {{"role", role}};
    store::Table spread{name + "_std", names, "standard deviation over " + over + " of " + what};
    spread.attributes = {{"role", "output"}};
    g.tables.push_back(mean);
    g.tables.push_back(spread);
  };
  for (const auto& param : models_[m].parameters) add(param.name, "the fitted " + param.name, "parameter");
  add("error", "the fit error", "error");
  return g;
}

SweepWorkload::LastLevel SweepWorkload::last_level(std::uint32_t, std::uint64_t,
                                                   const runtime::KeptResults& kept) const {
  LastLevel fits;
  const auto& grid = schedule_.levels().back();
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    const pbrfit::sweep::CellRef cell{final_level(), c};
    fits.push_back(kept.at<CellFits>({schedule_.stage_of(cell), schedule_.item_of(cell)}));
  }
  return fits;
}

SweepWorkload::Projection SweepWorkload::project(const runtime::StageTask<Nothing, LastLevel>& task) const {
  const auto& grid = schedule_.levels().back();
  if (task.input.size() != grid.cell_count()) throw RunError("sweep: a projection's input lacks last-level fits");
  const std::size_t axis = settings_.projections[task.item()];
  const auto reduced = projected_grid(task.item());
  std::vector<std::vector<std::vector<Moments>>> moments(models_.size());  // [model][reduced cell][quantity]
  for (std::size_t m = 0; m < models_.size(); ++m)
    moments[m].assign(reduced.cell_count(), std::vector<Moments>(models_[m].parameters.size() + 1));
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    auto at = grid.indices(c);
    at.erase(at.begin() + std::ptrdiff_t(axis));
    const std::size_t r = reduced.flat_index(at);
    const CellFits& fits = task.input[c];
    require_shapes(fits, shapes_);
    for (std::size_t m = 0; m < fits.size(); ++m) {
      for (std::size_t k = 0; k < fits[m].parameters.size(); ++k) moments[m][r][k].add(fits[m].parameters[k]);
      moments[m][r].back().add(fits[m].error);
    }
  }
  Projection values;
  for (const auto& model : moments)
    for (const auto& cell : model)
      for (const auto& q : cell) values.insert(values.end(), {q.mean, q.deviation()});
  return values;
}

void SweepWorkload::check_projection(const StageItem& at, const Projection& values) const {
  const auto reduced = projected_grid(at.item());
  std::size_t expected = 0;
  for (const auto& model : models_) expected += reduced.cell_count() * (model.parameters.size() + 1) * 2;
  if (values.size() != expected) throw RunError("a sweep projection result has the wrong length");
}

std::vector<store::Block> SweepWorkload::projection_blocks(const StageItem& at, const Projection& values) const {
  const WorkItemId id = at.id;
  const auto reduced = projected_grid(id.item);
  std::vector<store::Block> out;
  std::size_t next = 0;
  for (std::size_t m = 0; m < models_.size(); ++m) {
    for (std::size_t c = 0; c < reduced.cell_count(); ++c) {
      const auto at = reduced.indices(c);
      const std::vector<std::uint64_t> offset(at.begin(), at.end()), ones(at.size(), 1);
      for (std::size_t k = 0; k <= models_[m].parameters.size(); ++k) {
        const std::string name = k < models_[m].parameters.size() ? models_[m].parameters[k].name : "error";
        out.push_back({projection_name(m, id.item), name, offset, ones, {values[next++]}});
        out.push_back({projection_name(m, id.item), name + "_std", offset, ones, {values[next++]}});
      }
    }
  }
  return out;
}

}  // namespace pbrfit::jobs::sweep
