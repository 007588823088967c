#pragma once
// The base BRDF of one micro-normal, sampled in the geometric frame (Nahmias 2022, section 3.4.1): the
// lobe f (n.l) of the texel whose normal is n, seen from the geometric view v.
//  - specular: GGX of width alpha, F = 1, height-correlated Smith; light directions by visible-normal
//    sampling (brdf/ggx_lobe.hpp), accepted with probability G2 / G1, so they follow the lobe exactly;
//  - diffuse: Lambert, cosine-distributed about n.
// The lobe is sampled in the texel's own frame with the view at elevation theta_q = acos(max(v.n, 0.01))
// and azimuth 0, then rotated so that z goes to n and that view to v (the thesis' R_1 R_0; when v is
// parallel to n the azimuth is that of Frame::from_z(n)). Samples may end below the geometric horizon.
//
// Contract: sample_base_lobe returns `count` unit directions, a pure function of its arguments and of the
// stream's state; it draws at most 64 count candidates and repeats accepted ones if that budget runs out.
#include <cstddef>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ebrdf {

enum class Component { specular, diffuse };

inline constexpr double min_view_cosine = 0.01;

struct BaseLobe {
  Component component = Component::specular;
  double alpha = 0.01;  // GGX width (specular only)
};

// The texel frame: z = the normal n, x = the view's direction within the tangent plane of n (when v is
// parallel to n, Frame::from_z(n)).
Frame texel_frame(const Vector3& n, const Vector3& v);

std::vector<Vector3> sample_base_lobe(const BaseLobe& lobe, const Vector3& normal, const Vector3& view,
                                           std::size_t count, RandomStream& random);

}  // namespace pbrfit::ebrdf
