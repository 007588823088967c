#pragma once
// Integrals of the clamped cosine D_o over the solid angle a planar polygon subtends from the origin
// (Lambert's formula; Baum, Rushmeier & Winget 1989; the analytic step of Heitz et al. 2016, section 3).
// A polygon is given by its vertices p_0 .. p_{n-1} (n >= 3) as points relative to the shading point, in
// order around the polygon; the plane of the polygon must not contain the origin.
//
// Invariants:
//  - clamped_cosine_polygon_integral clips the polygon to the upper half-space z >= 0 first, then sums the
//    edge integrals (1 / 2 pi) theta_i (n_i . z) of the clipped polygon; its value is in [0, 1] and does not
//    depend on the winding or on which vertex comes first (the light is two-sided);
//  - vector_form_factor is the unclipped (1 / 2 pi) sum_i theta_i n_i with n_i = normalize(p_i x p_{i+1}):
//    it points towards the polygon when the vertices wind clockwise as seen from the origin, and its z
//    component is the signed, unclipped clamped-cosine integral.
#include <span>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

double clamped_cosine_polygon_integral(std::span<const Vector3> vertices);

Vector3 vector_form_factor(std::span<const Vector3> vertices);

}  // namespace pbrfit::ltc
