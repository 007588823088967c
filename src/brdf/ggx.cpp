#include "pbrfit/brdf/ggx.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "fixed_view_visibility.hpp"

namespace pbrfit::brdf {
namespace {

// G1(x) = 1 / (1 + Lambda(x)) for exact Smith GGX, written without tan so that G1(0) = 0 when alpha > 0.
double smith_g1(double alpha, double x) {
  const double width = smith_width(alpha * alpha, x);
  return width > 0.0 ? 2.0 * x / (x + width) : 1.0;
}

// Schlick-GGX G1 with k = alpha / 2; G1 = 1 in the mirror limit alpha = 0.
double schlick_g1(double alpha, double x) {
  const double k = 0.5 * alpha;
  const double denominator = x * (1.0 - k) + k;
  return denominator > 0.0 ? x / denominator : 1.0;
}

}  // namespace

double ggx_distribution(double alpha, double n_dot_h) {
  if (n_dot_h < 0.0) return 0.0;
  const double alpha_squared = alpha * alpha;
  const double denominator = n_dot_h * n_dot_h * (alpha_squared - 1.0) + 1.0;
  if (denominator <= 0.0) return std::numeric_limits<double>::infinity();  // alpha = 0, h = n
  return alpha_squared / (std::numbers::pi * denominator * denominator);
}

double ggx_smith_lambda(double alpha, double n_dot_w) {
  if (alpha == 0.0) return 0.0;
  if (n_dot_w <= 0.0) return std::numeric_limits<double>::infinity();
  const double cos_squared = n_dot_w * n_dot_w;
  const double alpha_tan_squared = alpha * alpha * (1.0 - cos_squared) / cos_squared;
  // (-1 + sqrt(1 + a)) / 2 == a / (2 (1 + sqrt(1 + a))), without cancellation for small a.
  return alpha_tan_squared / (2.0 * (1.0 + std::sqrt(1.0 + alpha_tan_squared)));
}

double smith_masking_shadowing(SmithVisibility visibility, double alpha, double n_dot_v, double n_dot_l) {
  if (n_dot_v <= 0.0 || n_dot_l <= 0.0) return 0.0;
  switch (visibility) {
    case SmithVisibility::separable:
      return smith_g1(alpha, n_dot_v) * smith_g1(alpha, n_dot_l);
    case SmithVisibility::separable_schlick:
      return schlick_g1(alpha, n_dot_v) * schlick_g1(alpha, n_dot_l);
    case SmithVisibility::height_correlated:
      return 1.0 / (1.0 + ggx_smith_lambda(alpha, n_dot_v) + ggx_smith_lambda(alpha, n_dot_l));
  }
  return 0.0;
}

double smith_visibility(SmithVisibility visibility, double alpha, double n_dot_v, double n_dot_l) {
  if (n_dot_v < 0.0 || n_dot_l < 0.0) return 0.0;
  switch (visibility) {
    case SmithVisibility::separable:
      return FixedViewVisibility<SmithVisibility::separable>(alpha, n_dot_v).visibility(n_dot_l);
    case SmithVisibility::separable_schlick:
      return FixedViewVisibility<SmithVisibility::separable_schlick>(alpha, n_dot_v).visibility(n_dot_l);
    case SmithVisibility::height_correlated:
      return FixedViewVisibility<SmithVisibility::height_correlated>(alpha, n_dot_v).visibility(n_dot_l);
  }
  return 0.0;
}

}  // namespace pbrfit::brdf
