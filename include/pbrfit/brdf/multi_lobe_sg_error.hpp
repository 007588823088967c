#pragma once
// How far a multi-lobe SG kernel (multi_lobe_sg.hpp) is from the cosine-weighted GGX response of one
// (alpha, view) cell, over the whole sphere (Pesce & Iwanicki 2015, sections 7.3 and 7.6):
//   squared_error = integral over the sphere of (rho(w) - kernel(w))^2 dw,
// rho from ggx_lobe.hpp (F = 1, height-correlated Smith; 0 below the horizon, so kernels that leak
// below it are penalized). Estimated by deterministic QMC with multiple importance sampling
// (integrate/mis_estimator.hpp): the GGX target's visible-normal sampling and each SG lobe's exact
// sampling, `samples_per_strategy` Halton points each, balance heuristic.
//
// Invariants: a pure function of (alpha, cos theta_v, lobe_count, samples, parameters): same inputs, same
// bits; >= 0; the Halton points and the target's own samples (direction, value, density) are made once by
// the constructor, so an estimate evaluates GGX only at the lobes' samples. The course used 30k-50k samples.
#include <cstddef>
#include <vector>

#include "pbrfit/brdf/multi_lobe_sg.hpp"
#include "pbrfit/brdf/ggx_lobe.hpp"

namespace pbrfit::brdf {

class MultiLobeSgError {
 public:
  // Throws std::invalid_argument for alpha <= 0, cos theta_v outside (0, 1], lobe_count < 2 or 0 samples.
  MultiLobeSgError(double alpha, double cos_theta_view, std::size_t lobe_count, std::size_t samples_per_strategy);

  std::size_t lobe_count() const { return lobe_count_; }
  const GgxLobe& target() const { return target_; }
  // integral of rho over the sphere (the directional albedo, by adaptive cubature, brdf/split_sum_dfg.hpp).
  double target_integral() const { return target_integral_; }
  // integral of rho^2 (the squared error of the zero kernel), estimated with the target's samples only.
  double target_squared_norm() const { return target_squared_norm_; }

  // With the amplitude as given (the four-parameter variant).
  double squared_error(const MultiLobeSgParameters& parameters) const;
  // With the amplitude replaced so the kernel integrates to target_integral() (the three-parameter variant).
  double squared_error_normalized(const MultiLobeSgParameters& parameters) const;

 private:
  struct TargetSample {
    Vector3 direction;
    double value = 0.0;
    double pdf = 0.0;
  };
  GgxLobe target_;
  std::size_t lobe_count_;
  std::vector<std::array<double, 2>> points_;
  std::vector<TargetSample> target_samples_;
  double target_integral_ = 0.0;
  double target_squared_norm_ = 0.0;
};

}  // namespace pbrfit::brdf
