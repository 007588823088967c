#pragma once
// The Disney diffuse environment-lighting lobe of one (roughness, n.v) cell (Pesce & Iwanicki 2015,
// section 6.3): the cosine-weighted Disney diffuse BRDF (disney_diffuse.hpp) for v = (sqrt(1 - mu^2), 0, mu)
// projected onto SH by adaptive cubature, its optimal linear direction d, the blend factor beta with
// d parallel to (1 - beta) n + beta v, and the zonal coefficients ZH0..ZH2 of the lobe about d.
//
// Invariants: roughness in [0, 1] and mu = n.v in [0, 1] (std::invalid_argument otherwise); the lobe is
// mirror-symmetric about the x-z plane, so sh[1], sh[4], sh[5] vanish up to the integration error and d
// lies in that plane; beta = 0 at mu = 1, where n = v and beta is undefined.
#include <cstddef>

#include "pbrfit/brdf/spherical_harmonics.hpp"
#include "pbrfit/integrate/adaptive_cubature.hpp"

namespace pbrfit::brdf {

struct DisneyDiffuseLobe {
  ShCoefficients sh{};
  Vector3 direction = Vector3::UnitZ();  // optimal linear direction
  double beta = 0.0;
  ZonalCoefficients zh{};                // ZH0, ZH1, ZH2 about direction
  double error_estimate = 0.0;           // of the SH integrals (absolute)
  std::size_t evaluations = 0;
  bool converged = false;
};

DisneyDiffuseLobe disney_diffuse_lobe(double roughness, double n_dot_v, const integrate::AdaptiveOptions& options);

// beta such that d is parallel to (1 - beta) n + beta v, for d in the x-z plane and v = (sqrt(1-mu^2), 0, mu):
// beta = d_x / (sin_v d_z + d_x (1 - mu)); 0 when sin_v = 0. Negative when d leans away from v.
double blend_factor_beta(const Vector3& direction, double n_dot_v);

// The lobe axis the blend factor gives: normalize((1 - beta) n + beta v).
Vector3 blended_direction(double beta, double n_dot_v);

}  // namespace pbrfit::brdf
