#pragma once
// The multi-lobe spherical Gaussian kernel of Pesce & Iwanicki 2015, section 7.6: N >= 2 SG lobes in the
// plane of n and v, sharing lambda, controlled by four outer parameters. In the shading frame with the
// view v = (sin theta_v, 0, cos theta_v), the lobes sit across the normal from v: lobe i has the axis
// (-sin theta_i, 0, cos theta_i) and, by equation (11) as printed in the course,
//   theta_i     = (2i/(N-1) - 1) spread + theta_center,                          i = 0..N-1
//   amplitude_i = norm exp(-(spread/3) (((i+1) - (N+1)/2) (2i/(N-1) - 1))^2).
// The course's constraint spread <= theta_center is applied by clamping (so the error is flat beyond it).
// norm is either free (`amplitude`) or set so that the kernel integrates to the target's integral.
#include <cstddef>
#include <vector>

#include "pbrfit/brdf/spherical_gaussian.hpp"

namespace pbrfit::brdf {

struct MultiLobeSgParameters {
  double theta_center = 0.0;  // radians
  double spread = 0.0;        // radians, clamped into [0, theta_center]
  double lambda = 1.0;        // shared sharpness, > 0
  double amplitude = 1.0;     // norm, > 0
};

// Throws std::invalid_argument for lobe_count < 2 or lambda <= 0.
std::vector<SphericalGaussian> multi_lobe_sg_lobes(const MultiLobeSgParameters& parameters, std::size_t lobe_count);

double multi_lobe_sg_value(const std::vector<SphericalGaussian>& lobes, const Vector3& w);
double multi_lobe_sg_integral(const std::vector<SphericalGaussian>& lobes);

// The same parameters with `amplitude` replaced by the norm that makes the kernel integrate to `integral`.
MultiLobeSgParameters normalized_to(const MultiLobeSgParameters& parameters, std::size_t lobe_count, double integral);

}  // namespace pbrfit::brdf
