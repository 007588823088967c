#pragma once
// The base BRDF of one micro-normal as MIP-0 shading shows it (plane_renderer.hpp's ground truth and its
// renders below two texels per pixel): an LTC in the texel's own frame, where z is the normal n and the
// view v lies in the xz plane at elevation acos(max(v.n, 0.01)) (the thesis' R_1 R_0; when v is parallel
// to n the azimuth is that of Frame::from_z(n)):
//  - specular: the base GGX LTC at that elevation (ggx_ltc_curve.hpp: GGX of width alpha, F = 1,
//    height-correlated Smith, fitted once), amplitude the lobe's albedo;
//  - diffuse: Lambert, the clamped cosine itself (M = I, amplitude 1).
// The effective BRDFs of the mip levels pool these very lobes, so that a footprint whose texels share one
// normal gives back the LTC that MIP-0 shading uses, and the levels and MIP 0 show the same surface.
// A sample is normalize(M w) for the clamped-cosine direction w of a point of the unit square, turned
// from the texel frame to the geometric one; it may lie below the geometric horizon.
//
// Contract: pure, deterministic functions; stratified_point(k, n, s) for k = 0 .. n-1 covers the unit
// square evenly, and so does every residue class k = t mod m of it (each texel of a pooled footprint
// draws from the whole square, not from a strip of it).
#include <array>
#include <cstddef>
#include <optional>

#include "pbrfit/ebrdf/ggx_ltc_curve.hpp"
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

class BaseLobeLtc {
 public:
  // Specular lobes fit the GGX LTC curve (points as GgxLtcCurve's default, the renderer's curve).
  explicit BaseLobeLtc(const BaseLobe& lobe);

  const BaseLobe& lobe() const { return lobe_; }
  // The lobe of the micro-normal n seen from v, in its texel frame.
  LtcLookup at(const Vector3& n, const Vector3& v) const;

 private:
  BaseLobe lobe_;
  std::optional<GgxLtcCurve> curve_;
};

// A direction of the lobe `ltc` (in the texel frame `frame`) in the geometric frame, from the point
// (u[0], u[1]) of the unit square.
Vector3 sample_base_lobe(const LtcLookup& ltc, const Frame& frame, const std::array<double, 2>& u);

// Point k of n stratified points of the unit square, shifted by `shift` modulo 1 (a Cranley-Patterson
// rotation): ((k + 1/2) / n, frac(k / golden ratio)), a Fibonacci-like lattice whose residue classes
// modulo any m are themselves spread over the square.
std::array<double, 2> stratified_point(std::size_t k, std::size_t n, const std::array<double, 2>& shift);

}  // namespace pbrfit::ebrdf
