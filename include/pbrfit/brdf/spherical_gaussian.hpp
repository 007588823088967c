#pragma once
// A spherical Gaussian lobe (Pesce & Iwanicki 2015, sections 7.2 and 7.6):
//   SG(w) = c exp(-lambda (1 - w . a)),   integral over the sphere = c 2 pi (1 - exp(-2 lambda)) / lambda,
// and its exact importance sampling: pdf = SG / integral, drawn by inverting the CDF in cos theta about a,
//   cos theta = 1 + log(1 - (1 - exp(-2 lambda)) u1) / lambda,  phi = 2 pi u2.
// Invariants: unit axis, lambda > 0 (the caller's duty); sample() returns unit vectors, continuous in
// (u1, u2); every expression is written with expm1/log1p so that it stays accurate for small lambda.
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

struct SphericalGaussian {
  Vector3 axis = Vector3::UnitZ();
  double sharpness = 1.0;  // lambda
  double amplitude = 1.0;  // c

  double value(const Vector3& w) const;
  double integral() const;
  double pdf(const Vector3& w) const;  // value / integral, independent of the amplitude
  Vector3 sample(double u1, double u2) const;
};

}  // namespace pbrfit::brdf
