#pragma once
// Internal: the Smith visibility V = G / (4 (n.v) (n.l)) with the view direction and alpha fixed, in
// forms that are finite as n.v or n.l tend to 0 when alpha > 0. Inline so that integrands can hoist
// the view-dependent term and call visibility() per light direction without a function call.
#include <cmath>

#include "pbrfit/brdf/ggx.hpp"

namespace pbrfit::brdf {

// x * sqrt(1 + alpha^2 tan^2(theta)) for x = cos(theta); equals alpha at x = 0.
inline double smith_width(double alpha_squared, double x) {
  return std::sqrt(x * x * (1.0 - alpha_squared) + alpha_squared);
}

// V = numerator() / denominator(n.l); the split lets integrands fold the division into their own.
template <SmithVisibility Convention>
class FixedViewVisibility {
 public:
  FixedViewVisibility(double alpha, double n_dot_v)
      : alpha_squared_(alpha * alpha), n_dot_v_(n_dot_v), k_(0.5 * alpha) {
    if constexpr (Convention == SmithVisibility::separable_schlick) {
      view_term_ = n_dot_v * (1.0 - k_) + k_;
    } else {
      view_term_ = smith_width(alpha_squared_, n_dot_v);
    }
  }

  static constexpr double numerator() {
    if constexpr (Convention == SmithVisibility::height_correlated) return 0.5;
    if constexpr (Convention == SmithVisibility::separable) return 1.0;
    return 0.25;
  }

  // Positive for n.l >= 0 when alpha > 0.
  double denominator(double n_dot_l) const {
    if constexpr (Convention == SmithVisibility::height_correlated) {
      return n_dot_l * view_term_ + n_dot_v_ * smith_width(alpha_squared_, n_dot_l);
    } else if constexpr (Convention == SmithVisibility::separable) {
      return (n_dot_v_ + view_term_) * (n_dot_l + smith_width(alpha_squared_, n_dot_l));
    } else {
      return view_term_ * (n_dot_l * (1.0 - k_) + k_);
    }
  }

  // V(v, l) for n.l >= 0.
  double visibility(double n_dot_l) const { return numerator() / denominator(n_dot_l); }

  // The terms of denominator(), for vector code that evaluates it over many n.l (dfg_line_kernels.hpp).
  double alpha_squared() const { return alpha_squared_; }
  double view_term() const { return view_term_; }
  double k() const { return k_; }

 private:
  double alpha_squared_;
  double n_dot_v_;
  double k_;                // Schlick-GGX k = alpha / 2 (used by separable_schlick only)
  double view_term_ = 0.0;  // the factor of the denominator that depends on v only
};

}  // namespace pbrfit::brdf
