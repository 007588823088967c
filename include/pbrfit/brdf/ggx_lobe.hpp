#pragma once
// The cosine-weighted GGX specular lobe with F = 1 and height-correlated Smith G2 (D, Lambda and G2 from
// ggx.hpp), the target of the GGX LTC table:
//   rho(v, l) = f(v, l) (n.l) = D(n.h) G2(v, l) / (4 n.v),   h = normalize(v + l),
// and 0 when n.v <= 0, n.l <= 0 or v = -l. alpha > 0 (alpha = 0 is a Dirac and gives +inf at h = n).
//
// GgxLobe is that lobe for one view in the x-z plane (lobe.hpp), sampled by reflecting visible normals
// about v (Heitz 2018): pdf(l) = G1(v) D(h) / (4 cos theta_v) on the whole sphere (it integrates to 1;
// directions below the horizon keep their density but have rho = 0).
//
// Invariants: alpha > 0 and 0 < cos theta_v <= 1 (the constructor throws std::invalid_argument otherwise);
// rho(l) / pdf(l) = G2(v, l) / G1(v) wherever l.z > 0; sample() is continuous in (u1, u2) and returns unit l.
#include "pbrfit/brdf/lobe.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

double ggx_cosine_weighted(double alpha, const Vector3& v, const Vector3& l);

// The mirror direction of w about n = +z: (-w.x, -w.y, w.z).
Vector3 mirror_about_normal(const Vector3& w);

class GgxLobe final : public Lobe {
 public:
  GgxLobe(double alpha, double cos_theta_view);

  double alpha() const { return alpha_; }
  double view_masking() const { return masking_; }  // G1(v)

  Evaluation evaluate(const Vector3& l) const override;
  // evaluate() over many directions as vector code of the process's kernel set (ggx_lobe_batch.hpp).
  void evaluate_many(std::span<const Vector3> l, std::span<Evaluation> out) const override;
  void value_many(std::span<const Vector3> l, std::span<double> out) const override;
  Vector3 sample(double u1, double u2) const override;

 private:
  double alpha_;
  double view_lambda_;  // Lambda(v)
  double masking_;      // G1(v) = 1 / (1 + Lambda(v))
};

// A direction drawn from the GGX visible normals of view v (v.z > 0) for width alpha, reflected about v.
Vector3 sample_ggx_visible_reflection(double alpha, const Vector3& v, double u1, double u2);

}  // namespace pbrfit::brdf
