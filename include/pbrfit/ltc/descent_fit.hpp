#pragma once
// A fast deterministic fit of a full 3 x 3 LTC to a set of directions: gradient descent on the sliced
// Wasserstein distance (sliced_wasserstein.hpp: fixed axes and base samples, analytic gradient), from the
// best of the moment-matched start (moment_matching.hpp), the identity (the cosine) and an optional warm
// start.
// SW is scale-invariant, so its gradient is orthogonal to M: each accepted step is followed by a
// rescale to unit Frobenius norm, which keeps step sizes meaningful. The step adapts: x1.3 after an
// accepted step (the trial lowered SW), x0.5 after a rejected one.
//
// Contract: deterministic; 2 + iterations gradient evaluations (+1 for a warm start); `distance`
// never exceeds `start_distance`; the matrix has unit Frobenius norm.
#include <cstddef>
#include <span>

#include "pbrfit/ltc/anisotropic_fit.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

struct DescentFitOptions {
  std::size_t axes = 12;
  std::size_t iterations = 30;
  double initial_step = 0.5;
};

AnisotropicFit fit_ltc_by_descent(std::span<const Vector3> targets, double amplitude, const Matrix3* warm_start,
                                  const DescentFitOptions& options);

}  // namespace pbrfit::ltc
