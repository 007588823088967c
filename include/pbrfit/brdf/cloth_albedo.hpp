#pragma once
// The cloth channel of a DFG table, as Filament's cmgen computes it for sheen (its DFV_Charlie_Uniform, the
// blue channel of its DFG LUT): the directional albedo of the Charlie sheen distribution (Estevez & Kulla
// 2017) with the visibility of Ashikhmin & Neubelt (Neubelt & Pettineo 2013), F = 1:
//   E_cloth(n.v, alpha) = integral over l above the horizon of D_Charlie(h) V(n.v, n.l) (n.l) dl,
//   V = 1 / (4 (n.l + n.v - n.l n.v))    (sheen.hpp: charlie_distribution, neubelt_visibility),
// with alpha the distribution's width (cmgen: the perceptual roughness squared). Not the Lambda visibility of
// the `charlie` LTC family: this is cmgen's choice, and its albedo exceeds 1 at grazing views and low alpha.
//
// Integrated adaptively in half-vector coordinates (theta_h up to the horizon theta_max(phi), phi over half
// the circle by symmetry), with quadratic maps that widen the horizon edge, where the distribution's grazing
// peak meets the horizon, and the azimuth where the horizon jumps at grazing views.
//
// Contract: n_dot_v in [0, 1] and alpha >= 0 (std::invalid_argument otherwise); alpha = 0 gives 0 (the
// distribution is a ring of half vectors in the surface plane, whose lights lie below the horizon);
// deterministic; error_estimate bounds |value - exact| as the adaptive integrator's estimate does.
#include <cstddef>

#include "pbrfit/integrate/adaptive_cubature.hpp"

namespace pbrfit::brdf {

struct ClothAlbedo {
  double value = 0.0;
  double error_estimate = 0.0;
  std::size_t evaluations = 0;
  bool converged = false;
};

ClothAlbedo integrate_cloth_albedo(double n_dot_v, double alpha, const integrate::AdaptiveOptions& options);

}  // namespace pbrfit::brdf
