#pragma once
// What a `sweep` job fits (docs/job-files.md, kind `sweep`): a problem is defined over named grid axes,
// offers one or more models with named, bounded parameters, and makes, per cell, a target that every
// model is fitted to (computed once per cell: a ground truth, a sample set, a tabulated lobe).
//
// Contract: a problem is immutable once built and shared read-only by all compute threads of a process;
// target() is a pure function of the cell's coordinates (axis values, in the order of axes()); a target's
// problem() and outputs() are pure. outputs() returns ModelInfo::output_width() values in output order.
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pbrfit/optimize/parameter_transform.hpp"
#include "pbrfit/optimize/tolerance_schedule.hpp"
#include "pbrfit/store/result_layout.hpp"
#include "pbrfit/sweep/cell_fit.hpp"
#include "pbrfit/sweep/grid_axis.hpp"
#include "pbrfit/sweep/level_grid.hpp"

namespace pbrfit::jobs::sweep {

struct ProblemAxis {
  std::string name;
  std::string description;   // including the parametrization
  double min = 0.0, max = 1.0;  // the values the problem accepts
  pbrfit::sweep::GridAxis default_axis;
};

// A derived value stored per cell beside the fitted parameters.
struct ModelOutput {
  std::string name;
  std::string description;
  std::string role = "output";        // docs/report.md: output, error, anchor_error
  std::string anchor = {};            // anchor_error: whose model
  std::string compares_with = {};     // anchor_error: the error table it is compared with
  std::size_t components = 1;         // > 1: a table with an extra innermost axis `<name>_component`
  store::ValueType type = store::ValueType::f64;
};

struct ModelInfo {
  std::string name;
  std::string description;
  std::vector<optimize::Parameter> parameters;  // default bounds and transforms
  std::string error_description;               // what the `error` table holds
  std::vector<ModelOutput> outputs;
  // The scalar output the headline summarizes instead of `error` (empty: the error), and its words; for
  // LTC tables the relative L2 error, in per cent, which is what users compare (docs/results-sweep.md).
  std::string headline_output = {};
  std::string headline_label = {};

  std::size_t output_width() const;
  // Where headline_output starts in a fit's outputs; nullopt for the error.
  std::optional<std::size_t> headline_offset() const;
};

class CellTarget {
 public:
  virtual ~CellTarget() = default;
  // The fitting problem of model `model` over `parameters` (the model's, possibly with the job's bounds).
  virtual pbrfit::sweep::CellProblem problem(std::size_t model, const std::vector<optimize::Parameter>& parameters) const = 0;
  virtual std::vector<double> outputs(std::size_t model, std::span<const double> parameters) const = 0;
};

// A check render of the finished table (optional): images of a scene shaded by the last level's fits (as an
// engine would use them) and by ground truth, one image per value of `image_axis`, each reading the last
// level's cells `cells[image]` (flat indices, in the order render() receives their outputs). With `curves`,
// each image also has curves over (sets, positions) per curve layer (LTC tables: the lobes in the plane of
// incidence at two views), computed with the image's first band and written to `<model>/<curves.group>`.
struct RenderCurves {
  std::string group, description;
  std::string set_axis, set_description;
  std::vector<double> sets;
  std::string position_axis, position_description;
  std::vector<double> positions;
  struct Layer {
    std::string name, description;
  };
  std::vector<Layer> layers;

  std::size_t size() const { return layers.size() * sets.size() * positions.size(); }
};

struct RenderPlan {
  std::string description;  // the scene, for the result group
  std::size_t resolution = 0;  // pixels a side
  std::size_t band_rows = 8;   // rows per work item
  std::string image_axis;
  std::string image_axis_description;
  std::vector<double> image_values;
  std::vector<std::vector<std::size_t>> cells;
  std::vector<std::vector<std::vector<double>>> coordinates;  // of those cells, per image
  struct Layer {
    std::string name, description;
  };
  std::vector<Layer> layers;  // per model
  std::optional<RenderCurves> curves;
};

class SweepProblem {
 public:
  virtual ~SweepProblem() = default;
  virtual std::string description() const = 0;
  virtual std::vector<ProblemAxis> axes() const = 0;
  virtual std::vector<ModelInfo> models() const = 0;
  // Settings a reader needs (the objective, its integrator and tolerances), as group attributes.
  virtual std::map<std::string, std::string> attributes() const = 0;
  // The tolerance schedule the fitter passes to the objective (cooperative accuracy); objectives that
  // ignore their tolerance keep the default.
  virtual optimize::ToleranceSchedule tolerance_schedule() const { return optimize::ToleranceSchedule::constant(0.0); }
  // Throws RunError when the cell's target cannot be computed (e.g. an integral misses its tolerance).
  virtual std::unique_ptr<CellTarget> target(std::span<const double> coordinates) const = 0;
  // The check render of a finished table over the last level's grid, if the problem has one.
  virtual std::optional<RenderPlan> render_plan(const pbrfit::sweep::LevelGrid&) const { return std::nullopt; }
  // Rows [first_row, first_row + rows) of image `image` of model `model` (an index into models()): layers x
  // rows x resolution values, layer-major, each layer row-major from its top row, then for the first band
  // (first_row 0) the image's curves (layers x sets x positions); `outputs` are the model's outputs at
  // plan.cells[image], in order. Pure; throws RunError where a pixel cannot be computed.
  virtual std::vector<double> render(std::size_t model, const RenderPlan& plan, std::size_t image,
                                     std::size_t first_row, std::size_t rows,
                                     std::span<const std::vector<double>> outputs) const;
};

}  // namespace pbrfit::jobs::sweep
