#pragma once
// The Oren-Nayar diffuse BRDF, the qualitative model of Oren & Nayar (1994), albedo 1, weighted by the
// cosine of the light:
//   f = (1 / pi) (A + B max(0, cos(phi_l - phi_v)) sin(a) tan(b)),   a = max(theta_l, theta_v),
//   b = min(theta_l, theta_v),  A = 1 - 0.5 s^2 / (s^2 + 0.33),  B = 0.45 s^2 / (s^2 + 0.09),
//   rho(v, l) = f (n.l),
// for the facet-slope standard deviation s (radians) in the shading frame (n = +z); 0 when n.v < 0 or
// n.l <= 0. s = 0 is Lambert's (n.l) / pi. Where either direction is the normal the azimuth term is 0.
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

double oren_nayar_cosine_weighted(double sigma, const Vector3& v, const Vector3& l);

// rho for one view v, with A, B and the view's sine computed once.
class OrenNayarView {
 public:
  OrenNayarView(double sigma, const Vector3& v);
  double operator()(const Vector3& l) const;

 private:
  Vector3 v_;
  double a_, b_, sin_v_;
};

}  // namespace pbrfit::brdf
