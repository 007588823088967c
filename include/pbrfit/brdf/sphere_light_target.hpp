#pragma once
// The spherical-light ground truth of one cell (alpha, light), tabulated once over the view hemisphere
// so that a model (sphere_light_models.hpp) can be scored cheaply many times (Pesce & Iwanicki 2015,
// section 4.2: for each roughness, light size and incidence, fit a lobe over the views).
//
// Views: a product quadrature in polar coordinates (theta', phi') about the mirror direction of the
// light's centre, where the lobe peaks. theta' = 2 atan(s t / (1 - t)) for t in [0, 1) grades the nodes
// towards the peak (half of them within theta' < 2 atan(s), s = alpha + sin gamma); t and phi' are
// split into equal panels of the 15-point Kronrod rule. Views below the horizon keep their weight
// (the ground truth and every model are 0 there).
//
// Invariants: nodes and weights depend only on (alpha, light, grid); the weights sum to the solid angle of
// the sphere up to quadrature error; error() and norm() are pure.
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

#include "pbrfit/brdf/sphere_light.hpp"

namespace pbrfit::brdf {

struct ViewGrid {
  int radial_panels = 2;   // 15 nodes each, in t
  int azimuth_panels = 2;  // 15 nodes each, in phi'
};

class SphereLightTarget {
 public:
  // Throws what sphere_light_response throws. `options` is used for every view's cap integral.
  SphereLightTarget(double alpha, const SphereLight& light, const ViewGrid& grid,
                    const integrate::AdaptiveOptions& options);

  struct Node {
    Vector3 view;
    double weight = 0.0;  // solid angle
    double truth = 0.0;   // sphere_light_response at this view
  };
  const std::vector<Node>& nodes() const { return nodes_; }
  double alpha() const { return alpha_; }
  const SphereLight& light() const { return light_; }
  double largest_error_estimate() const { return largest_error_estimate_; }  // over the cap integrals
  std::size_t evaluations() const { return evaluations_; }                   // over the cap integrals
  bool converged() const { return converged_; }

  // The L^p distance over views between the truth and model(view): (sum w |truth - model|^p)^(1/p);
  // p = +inf gives the largest |truth - model| over the nodes. p >= 1.
  double error(const std::function<double(const Vector3&)>& model, double p = 2.0) const;
  // The L^p norm of the truth (error() of the zero model), to make errors relative.
  double norm(double p = 2.0) const;
  // The scale k minimizing the L2 error of k * model (a closed-form fit of a model's normalization):
  // sum w truth model / sum w model^2; 0 for a model that vanishes at every node.
  double least_squares_scale(const std::function<double(const Vector3&)>& model) const;

 private:
  double alpha_;
  SphereLight light_;
  std::vector<Node> nodes_;
  double largest_error_estimate_ = 0.0;
  std::size_t evaluations_ = 0;
  bool converged_ = true;
};

}  // namespace pbrfit::brdf
