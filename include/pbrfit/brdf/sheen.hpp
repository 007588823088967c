#pragma once
// Cloth and sheen lobes, Fresnel-free and weighted by the cosine of the light, in the shading frame (n = +z);
// each is 0 when n.v <= 0 or n.l <= 0.
//
// Charlie sheen (Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF"):
//   D(h) = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi),
//   rho(v, l) = D(h) / (4 n.v (1 + Lambda(v) + Lambda(l))),
//   Lambda(mu) = exp(L(mu)) for mu < 1/2, exp(2 L(1/2) - L(1 - mu)) otherwise,
//   L(x) = a / (1 + b x^c) + d x + e, the five coefficients interpolated between the paper's fits for
//   alpha = 0 and alpha = 1 with weight (1 - alpha)^2 on the former (the form of KHR_materials_sheen).
//   No terminator softening.
//
// Ashikhmin cloth (Ashikhmin & Premoze 2007, the "inverted Gaussian" distribution of Filament's cloth model)
// with Neubelt & Pettineo's (2013) visibility:
//   D(h) = (1 + 4 exp(-cot^2 theta_h / alpha^2) / sin^4 theta_h) / (pi (1 + 4 alpha^2)),
//   V = 1 / (4 (n.l + n.v - n.l n.v)),   rho(v, l) = D(h) V (n.l).
//
// Fabric Lambert (the cotton-wool diffuse lobe of Unity HDRP's fabric shader):
//   rho(v, l) = (1 - r / 2) (n.l) / pi   for its roughness r in [0, 1].
//
// Both distributions are normalized: the integral of D(h) (n.h) over the hemisphere is 1.
#include <cstddef>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

double charlie_distribution(double alpha, double n_dot_h);
double charlie_lambda(double alpha, double cosine);
double charlie_cosine_weighted(double alpha, const Vector3& v, const Vector3& l);

// Charlie's rho for one view v, with the interpolated coefficients of L and Lambda(v) computed once. rho goes
// through vector code of the active kernel set (core/kernel_set.hpp): its powers and Lambda(l) are Eigen's exp
// and log, within relative 1e-12 of std::pow and std::exp (unit-tested) and possibly different between sets
// in the last bits; one direction alone (operator(), charlie_cosine_weighted) gets the value it gets among
// many (many()). lambda() and Lambda(v) are the scalar std::pow and std::exp form.
class CharlieView {
 public:
  CharlieView(double alpha, const Vector3& v);
  double operator()(const Vector3& l) const;
  // out[i] = (*this)(l[i]) for i < n.
  void many(const Vector3* l, std::size_t n, double* out) const;
  double lambda(double cosine) const;

 private:
  double l_of(double x) const;
  double alpha_;
  Vector3 v_;
  double p_[5];
  double l_half_;  // L(1/2)
  double view_lambda_;
};

double ashikhmin_distribution(double alpha, double n_dot_h);
double neubelt_visibility(double n_dot_v, double n_dot_l);
double ashikhmin_cosine_weighted(double alpha, const Vector3& v, const Vector3& l);

double fabric_lambert_cosine_weighted(double roughness, const Vector3& v, const Vector3& l);

}  // namespace pbrfit::brdf
