#pragma once
// The cosine-weighted GGX specular lobe for arbitrary unit directions in the shading frame (n = +z), with
// F = 1 and height-correlated Smith G2 (the convention of ltc/ggx_target.hpp, built from brdf/ggx.hpp):
//   rho(v, l) = f(v, l) (n.l) = D(n.h) G2(v, l) / (4 n.v),   h = normalize(v + l),
// and 0 when n.v <= 0, n.l <= 0 or v = -l. alpha > 0 (alpha = 0 is a Dirac and gives +inf at h = n).
#include "pbrfit/ltc/vector.hpp"

namespace pbrfit::brdf {

double ggx_cosine_weighted(double alpha, const ltc::Vector3& v, const ltc::Vector3& l);

// The mirror direction of w about n = +z: (-w.x, -w.y, w.z).
ltc::Vector3 mirror_about_normal(const ltc::Vector3& w);

}  // namespace pbrfit::brdf
