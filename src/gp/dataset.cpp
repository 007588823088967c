#include "pbrfit/gp/dataset.hpp"

#include <stdexcept>

namespace pbrfit::gp {

void validate(const Dataset& dataset) {
  if (dataset.inputs.rows() < 1 || dataset.inputs.cols() < 1) {
    throw std::invalid_argument("a dataset needs at least one row and one input");
  }
  if (dataset.target.size() != dataset.inputs.rows()) throw std::invalid_argument("one target value per row");
  if (!dataset.inputs.allFinite() || !dataset.target.allFinite()) {
    throw std::invalid_argument("dataset values must be finite");
  }
  if (dataset.weights.size() == 0) return;
  if (dataset.weights.size() != dataset.inputs.rows()) throw std::invalid_argument("one weight per row");
  if (!dataset.weights.allFinite() || (dataset.weights < 0.0).any() || !(dataset.weights > 0.0).any()) {
    throw std::invalid_argument("weights must be finite, >= 0 and not all 0");
  }
}

}  // namespace pbrfit::gp
