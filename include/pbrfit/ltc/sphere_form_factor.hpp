#pragma once
// The horizon-clipped form factor of a spherical cap, the term behind ltc_2.w of the published tables
// (ltc_code fitLTC.cpp, genSphereTab; Snyder 1996 for the closed form; Hill & Heitz 2017 use it to
// approximate a polygon's clipped form factor from its unclipped vector form factor F).
//
// A cap of angular radius sigma centred at polar angle omega has the vector form factor F with |F| =
// sin^2 sigma and F.z = sin^2 sigma cos omega. Then
//  - cap_form_factor(cos omega, sin^2 sigma) = (1 / pi) * integral over the cap of max(0, cos theta);
//  - sphere_form_factor_ratio(z, length) = cap_form_factor(z, length) / length, the value the published
//    table stores at texel (i, j) for z = 2 i / 63 - 1, length = j / 63; its limit max(z, 0) at length 0;
//  - horizon_clipped_form_factor(F) = |F| * ratio(F.z / |F|, |F|), the sphere approximation of the
//    clipped form factor of whatever produced F (exact for a cap), with |F| clamped to [0, 1].
// All three are in [0, 1], continuous, and non-decreasing in z.
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

double cap_form_factor(double cos_centre, double sin_squared_radius);

double sphere_form_factor_ratio(double cos_centre, double length);

double horizon_clipped_form_factor(const Vector3& vector_form_factor);

}  // namespace pbrfit::ltc
