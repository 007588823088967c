#pragma once
// The parametrization of an isotropic-BRDF LTC after Heitz et al. 2016: a matrix acting in a frame aligned
// with the lobe's average direction Z (unit, in the x-z plane),
//   M = [X Y Z] * | m00  0   m02 |      X = (Z.z, 0, -Z.x),  Y = (0, 1, 0),
//                 |  0  m11   0  |
//                 | m20  0    1  |
// m00 and m11 scale the lobe across and along the view plane's normal, m02 skews it within the plane and
// m20 tilts it within the plane. The (2, 2) entry is 1 because an LTC does not depend on the scale of M.
// The paper's fitter keeps m20 = 0 and lets the frame carry the tilt; with m20 free the family is every LTC
// symmetric about the view plane (four degrees of freedom, as many as the published ltc_1 texel), and the
// frame only conditions the search. At normal view (Z = (0, 0, 1)) the lobe is rotationally symmetric:
// m00 = m11, m02 = m20 = 0.
//
// Invariants: det M = m11 (m00 - m02 m20), invertible when both factors are non-zero; the (0,1), (1,0),
// (1,2), (2,1) entries of M are 0, so shader_form() (shader_form.hpp) applies.
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

struct IsotropicParameters {
  double m00 = 1.0;
  double m11 = 1.0;
  double m02 = 0.0;
  double m20 = 0.0;
};

// [X Y Z] for a unit average direction in the x-z plane.
Matrix3 lobe_frame(const Vector3& average_direction);

Matrix3 isotropic_ltc_matrix(const IsotropicParameters& parameters, const Vector3& average_direction);

}  // namespace pbrfit::ltc
