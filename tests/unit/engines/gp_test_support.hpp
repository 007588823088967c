#pragma once
// Shared by the gp tests: datasets from a function, random programs over every operator.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>

#include "kernel_set_scope.hpp"
#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/dataset.hpp"
#include "pbrfit/gp/program_shape.hpp"
#include "pbrfit/gp/variation.hpp"

namespace gp_test {

using kernel_test::KernelSetScope;

// `rows` rows of `inputs` uniform inputs in [lower, upper], target f(row).
inline pbrfit::gp::Dataset sampled_dataset(std::size_t rows, std::size_t inputs, double lower, double upper,
                                           const std::function<double(std::span<const double>)>& f,
                                           std::uint64_t seed = 1) {
  pbrfit::gp::Dataset dataset;
  dataset.inputs.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(inputs));
  dataset.target.resize(static_cast<Eigen::Index>(rows));
  pbrfit::RandomStream random(seed, 0);
  double row[8] = {};
  for (Eigen::Index r = 0; r < dataset.inputs.rows(); ++r) {
    for (Eigen::Index c = 0; c < dataset.inputs.cols(); ++c) {
      row[c] = lower + (upper - lower) * random.uniform();
      dataset.inputs(r, c) = row[c];
    }
    dataset.target[r] = f(std::span<const double>(row, inputs));
  }
  return dataset;
}

// Programs of up to 40 instructions over every operator, with constants.
inline pbrfit::gp::ProgramShape wide_shape(std::size_t inputs) {
  pbrfit::gp::ProgramShape shape;
  shape.operators = pbrfit::gp::all_operators();
  shape.input_count = inputs;
  shape.max_length = 40;
  shape.initial_min_length = 1;
  shape.initial_max_length = 40;
  shape.constant_probability = 0.3;
  shape.constant_min = -3.0;
  shape.constant_max = 3.0;
  return shape;
}

inline pbrfit::gp::Program random_program(const pbrfit::gp::ProgramShape& shape, std::uint64_t seed,
                                          std::uint64_t index) {
  pbrfit::RandomStream random(seed, index);
  return pbrfit::gp::random_program(shape, random);
}

}  // namespace gp_test
