#include "pbrfit/brdf/roughness.hpp"

namespace pbrfit::brdf {

double alpha_from(RoughnessParametrization parametrization, double axis_value) {
  switch (parametrization) {
    case RoughnessParametrization::perceptual:
      return axis_value * axis_value;
    case RoughnessParametrization::linear:
      return axis_value;
    case RoughnessParametrization::gloss: {
      const double roughness = 1.0 - axis_value;
      const double squared = roughness * roughness;
      return squared * squared;
    }
  }
  return axis_value;
}

const char* formula(RoughnessParametrization parametrization) {
  switch (parametrization) {
    case RoughnessParametrization::perceptual:
      return "alpha = r^2";
    case RoughnessParametrization::linear:
      return "alpha = r";
    case RoughnessParametrization::gloss:
      return "alpha = (1 - g)^4";
  }
  return "";
}

}  // namespace pbrfit::brdf
