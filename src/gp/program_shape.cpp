#include "pbrfit/gp/program_shape.hpp"

#include <cmath>
#include <stdexcept>

#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {
namespace {

bool is_probability(double p) { return p >= 0.0 && p <= 1.0; }

}  // namespace

void validate(const ProgramShape& shape) {
  if (shape.operators.empty()) throw std::invalid_argument("a program shape needs at least one operator");
  if (shape.input_count < 1) throw std::invalid_argument("a program shape needs at least one input");
  if (!(1 <= shape.initial_min_length && shape.initial_min_length <= shape.initial_max_length &&
        shape.initial_max_length <= shape.max_length && shape.max_length <= max_program_length)) {
    throw std::invalid_argument("program lengths must satisfy 1 <= initial_min <= initial_max <= max <= 64");
  }
  if (!is_probability(shape.reference_probability) || !is_probability(shape.constant_probability)) {
    throw std::invalid_argument("program shape probabilities must be in [0, 1]");
  }
  if (!std::isfinite(shape.constant_min) || !std::isfinite(shape.constant_max) ||
      shape.constant_min > shape.constant_max) {
    throw std::invalid_argument("the constant range must be finite with constant_min <= constant_max");
  }
}

}  // namespace pbrfit::gp
