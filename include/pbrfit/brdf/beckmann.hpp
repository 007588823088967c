#pragma once
// The Beckmann microfacet distribution with its exact Smith masking, isotropic (Walter et al. 2007), and the
// Fresnel-free cosine-weighted lobe built from them as the LTC paper's reference fitter fits it:
//   D(h) = exp(-tan^2 theta_h / alpha^2) / (pi alpha^2 cos^4 theta_h)         (0 for n.h <= 0)
//   Lambda(w) = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)),  a = 1 / (alpha tan theta_w)
//   rho(v, l) = D(h) G2(v, l) / (4 n.v),  G2 = 1 / (1 + Lambda(v) + Lambda(l)) (height-correlated)
// in the shading frame (n = +z). D is normalized: the integral of D(h) (n.h) over the hemisphere is 1.
// rho is 0 when n.v <= 0, n.l <= 0 or v = -l; alpha > 0.
#include <cstddef>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

double beckmann_distribution(double alpha, double n_dot_h);
// 0 at normal incidence, +inf at n.w <= 0.
double beckmann_smith_lambda(double alpha, double n_dot_w);
double beckmann_cosine_weighted(double alpha, const Vector3& v, const Vector3& l);

// rho for one view v, with Lambda(v) computed once: BeckmannView(alpha, v)(l) = beckmann_cosine_weighted(alpha, v, l).
// rho goes through vector code of the active kernel set (core/kernel_set.hpp): D's and Lambda(l)'s exp are
// Eigen's, within relative 1e-12 of the scalar functions above (unit-tested) and possibly different between
// sets in the last bits; one direction alone gets the value it gets among many (many()). Lambda(v) is the
// scalar one.
class BeckmannView {
 public:
  BeckmannView(double alpha, const Vector3& v);
  double operator()(const Vector3& l) const;
  // out[i] = (*this)(l[i]) for i < n.
  void many(const Vector3* l, std::size_t n, double* out) const;

 private:
  double alpha_;
  Vector3 v_;
  double view_lambda_;
};

}  // namespace pbrfit::brdf
