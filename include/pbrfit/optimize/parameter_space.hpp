#pragma once
// A model's named parameters, each with bounds and a transform (parameter_transform.hpp). Optimizers
// search the internal box [0, 1]^n (a fixed parameter's interval is [0, 0]); the objective sees the
// model's parameters.
//
// Invariants: every parameter passed validate(); names are unique; internal and model vectors have
// size() entries, in the order the parameters were added.
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/objective.hpp"
#include "pbrfit/optimize/parameter_transform.hpp"

namespace pbrfit::optimize {

class ParameterSpace {
 public:
  ParameterSpace() = default;
  explicit ParameterSpace(std::vector<Parameter> parameters);

  // Throws std::invalid_argument for an invalid parameter or a duplicate name.
  ParameterSpace& add(Parameter parameter);

  std::size_t size() const { return parameters_.size(); }
  const std::vector<Parameter>& parameters() const { return parameters_; }
  // Throws std::out_of_range for an unknown name.
  std::size_t index_of(std::string_view name) const;

  Bounds internal_bounds() const;
  Bounds model_bounds() const;

  void to_internal(std::span<const double> model, std::span<double> internal) const;
  void from_internal(std::span<const double> internal, std::span<double> model) const;
  std::vector<double> to_internal(std::span<const double> model) const;
  std::vector<double> from_internal(std::span<const double> internal) const;

  // The model objective seen from the internal box: each point is mapped to model parameters first, in a
  // buffer the returned objective owns (no allocation per evaluation; one caller at a time).
  Objective internal_objective(Objective model_objective) const;

 private:
  std::vector<Parameter> parameters_;
};

}  // namespace pbrfit::optimize
