#pragma once
// What a sweep work item returns: one fit per model of the job, in the job's model order, as bytes for the
// runtime (checkpoints, messages) and back.
//
// Invariant: decode(encode(r), shapes) == r; decode throws RunError for bytes that do not hold exactly
// one fit of each shape (a damaged or foreign result).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pbrfit/core/bytes.hpp"

namespace pbrfit::jobs::sweep {

// Which start a cell's fit came from; the result's `start` table stores these codes.
enum class StartCode : std::uint8_t { global = 0, default_start = 1, neighbour = 2, parent = 3 };
inline constexpr const char* start_code_labels = "0=global,1=default,2=neighbour,3=parent";

struct ModelFit {
  std::vector<double> parameters;
  double error = 0.0;
  std::uint64_t evaluations = 0;
  StartCode start = StartCode::global;
  bool global_ran = false;
  std::vector<double> outputs;
  bool operator==(const ModelFit&) const = default;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(parameters, error, evaluations, start, global_ran, outputs);
  }
};

// A cell's result: a fit per model of the job, in job order.
using CellFits = std::vector<ModelFit>;

struct FitShape {
  std::size_t parameters = 0;
  std::size_t outputs = 0;
};

// Throws RunError unless the fits have the job's models' shapes and known start codes (a result read from a
// checkpoint or another rank).
void require_shapes(const CellFits& fits, const std::vector<FitShape>& shapes);

}  // namespace pbrfit::jobs::sweep
