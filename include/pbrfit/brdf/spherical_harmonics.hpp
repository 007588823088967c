#pragma once
// Real spherical harmonics of bands 0..2 (nine coefficients, "3rd-order SH", Pesce & Iwanicki 2015
// section 6.1), orthonormal over the sphere, without the Condon-Shortley phase (the graphics convention
// of Sloan 2008): index l*l + l + m for band l, order m = -l..l, i.e.
//   0: Y00 = 1/(2 sqrt(pi))
//   1: c1 y   2: c1 z   3: c1 x                           c1 = sqrt(3/(4 pi))
//   4: c2 xy  5: c2 yz  6: c20 (3z^2 - 1)  7: c2 xz  8: c2/2 (x^2 - y^2)   c2 = sqrt(15/(4 pi)), c20 = sqrt(5/(16 pi))
//
// Zonal harmonics: a function symmetric about an axis d has the expansion sum_l zh_l Y_l0(angle to d);
// zonal_coefficients() takes the SH of any function and returns the zh_l of its projection onto the
// functions symmetric about d, zh_l = sqrt(4 pi / (2l + 1)) sum_m c_lm Y_lm(d) (addition theorem); for a
// function already symmetric about d this is exactly the m = 0 coefficient after rotating d onto z.
#include <array>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

using ShCoefficients = std::array<double, 9>;
using ZonalCoefficients = std::array<double, 3>;

// Basis values at a unit direction w.
ShCoefficients sh_basis(const Vector3& w);

// The optimal linear direction (Sloan 2008): the unit vector along the band-1 coefficients,
// (c[3], c[1], c[2]) normalized; +z when they vanish.
Vector3 optimal_linear_direction(const ShCoefficients& sh);

ZonalCoefficients zonal_coefficients(const ShCoefficients& sh, const Vector3& axis);

}  // namespace pbrfit::brdf
