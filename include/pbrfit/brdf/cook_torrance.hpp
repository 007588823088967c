#pragma once
// The specular term of Cook-Torrance as the genBRDF paper prints it (Brady et al., equation 5, after Cook &
// Torrance 1982) with F = 1, k_s = 1 and k_d = 0, weighted by the cosine of the light:
//   f = (1 / pi) D G / ((n.l)(n.v)),   D = exp(-tan^2 delta / m^2) / (m^2 cos^4 delta),
//   G = min(1, 2 (n.h)(n.v) / (v.h), 2 (n.h)(n.l) / (v.h)),   delta = angle(n, h),
//   rho(v, l) = f (n.l) = D G / (pi n.v),
// in the shading frame (n = +z); 0 when n.v <= 0, n.l <= 0 or v = -l; m > 0. D carries no 1/pi (D / pi is the
// normalized Beckmann distribution) and the denominator is pi rather than 4, so this form is 4 times the
// normalized microfacet model with the same D and G: its directional albedo lies in [0, 4], not [0, 1].
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

// The V-cavity masking-shadowing term G of equation 5c.
double cook_torrance_geometry(double n_dot_h, double n_dot_v, double n_dot_l, double v_dot_h);
double cook_torrance_cosine_weighted(double m, const Vector3& v, const Vector3& l);

}  // namespace pbrfit::brdf
