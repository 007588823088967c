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
#include <span>
#include <string>
#include <vector>

#include "pbrfit/optimize/parameter_transform.hpp"
#include "pbrfit/optimize/tolerance_schedule.hpp"
#include "pbrfit/store/result_layout.hpp"
#include "pbrfit/sweep/cell_fit.hpp"
#include "pbrfit/sweep/grid_axis.hpp"

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

  std::size_t output_width() const;
};

class CellTarget {
 public:
  virtual ~CellTarget() = default;
  // The fitting problem of model `model` over `parameters` (the model's, possibly with the job's bounds).
  virtual pbrfit::sweep::CellProblem problem(std::size_t model, const std::vector<optimize::Parameter>& parameters) const = 0;
  virtual std::vector<double> outputs(std::size_t model, std::span<const double> parameters) const = 0;
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
};

}  // namespace pbrfit::jobs::sweep
