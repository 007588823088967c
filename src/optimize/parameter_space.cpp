#include "pbrfit/optimize/parameter_space.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace pbrfit::optimize {

ParameterSpace::ParameterSpace(std::vector<Parameter> parameters) {
  for (Parameter& parameter : parameters) add(std::move(parameter));
}

ParameterSpace& ParameterSpace::add(Parameter parameter) {
  validate(parameter);
  for (const Parameter& existing : parameters_) {
    if (existing.name == parameter.name) {
      throw std::invalid_argument("optimize: parameter '" + parameter.name + "' appears twice");
    }
  }
  parameters_.push_back(std::move(parameter));
  return *this;
}

std::size_t ParameterSpace::index_of(std::string_view name) const {
  for (std::size_t i = 0; i < parameters_.size(); ++i) {
    if (parameters_[i].name == name) return i;
  }
  throw std::out_of_range("optimize: no parameter named '" + std::string(name) + "'");
}

Bounds ParameterSpace::internal_bounds() const {
  Bounds bounds;
  for (const Parameter& parameter : parameters_) {
    bounds.lower.push_back(0.0);
    bounds.upper.push_back(parameter.lower == parameter.upper ? 0.0 : 1.0);
  }
  return bounds;
}

Bounds ParameterSpace::model_bounds() const {
  Bounds bounds;
  for (const Parameter& parameter : parameters_) {
    bounds.lower.push_back(parameter.lower);
    bounds.upper.push_back(parameter.upper);
  }
  return bounds;
}

void ParameterSpace::to_internal(std::span<const double> model, std::span<double> internal) const {
  for (std::size_t i = 0; i < parameters_.size(); ++i) internal[i] = optimize::to_internal(parameters_[i], model[i]);
}

void ParameterSpace::from_internal(std::span<const double> internal, std::span<double> model) const {
  for (std::size_t i = 0; i < parameters_.size(); ++i) model[i] = optimize::from_internal(parameters_[i], internal[i]);
}

std::vector<double> ParameterSpace::to_internal(std::span<const double> model) const {
  std::vector<double> internal(parameters_.size());
  to_internal(model, internal);
  return internal;
}

std::vector<double> ParameterSpace::from_internal(std::span<const double> internal) const {
  std::vector<double> model(parameters_.size());
  from_internal(internal, model);
  return model;
}

Objective ParameterSpace::internal_objective(Objective model_objective) const {
  return Objective([space = *this, model = std::vector<double>(size()), objective = std::move(model_objective)](
                       std::span<const double> internal, double tolerance) mutable {
    space.from_internal(internal, model);
    return objective(model, tolerance);
  });
}

}  // namespace pbrfit::optimize
