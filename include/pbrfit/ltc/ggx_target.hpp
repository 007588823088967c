#pragma once
// The lobe the isotropic LTC tables approximate: GGX with F = 1 and height-correlated Smith G2, weighted by
// the cosine of the light, for a view direction in the x-z plane, v = (sin theta_v, 0, cos theta_v):
//   rho(l) = f(v, l) (n . l) = D(h) G2(v, l) / (4 cos theta_v),   h = normalize(v + l),
// and 0 for l below the horizon. D, Lambda and G2 come from brdf/ggx.hpp.
//
// Sampling reflects visible normals about v (Heitz 2018): pdf(l) = G1(v) D(h) / (4 cos theta_v) on the whole
// sphere (it integrates to 1; directions below the horizon keep their density but have rho = 0).
//
// Invariants: alpha > 0 and 0 < cos theta_v <= 1 (the constructor throws std::invalid_argument otherwise);
// rho(l) / pdf(l) = G2(v, l) / G1(v) wherever l.z > 0; sample() is continuous in (u1, u2) and returns unit l.
#include "pbrfit/ltc/vector.hpp"

namespace pbrfit::ltc {

class GgxTarget {
 public:
  GgxTarget(double alpha, double cos_theta_view);

  double alpha() const { return alpha_; }
  const Vector3& view() const { return view_; }
  double view_masking() const { return masking_; }  // G1(v)

  struct Evaluation {
    double value = 0.0;  // rho(l)
    double pdf = 0.0;
  };
  Evaluation evaluate(const Vector3& l) const;
  Vector3 sample(double u1, double u2) const;

 private:
  double alpha_;
  Vector3 view_;
  double view_lambda_;  // Lambda(v)
  double masking_;      // G1(v) = 1 / (1 + Lambda(v))
};

}  // namespace pbrfit::ltc
