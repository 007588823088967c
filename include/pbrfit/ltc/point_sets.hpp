#pragma once
// Deterministic point sets behind the module's fixed-sample estimators, so that an estimate is a pure,
// reproducible function of its inputs.
//
//  - golden_lattice(n): the rank-1 lattice u_i = ((i + 1/2) / n, frac((i + 1/2) / phi)), phi the golden ratio,
//    i = 0..n-1; every point lies in the open square (0, 1)^2 and each column of width 1/n holds one point;
//  - axis_directions(n): n unit vectors spread over the upper hemisphere (a spherical Fibonacci set, z from
//    near 1 down to near 0); as projection axes they cover every direction up to sign, which is all a
//    one-dimensional projection distinguishes.
#include <array>
#include <cstddef>
#include <vector>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

std::vector<std::array<double, 2>> golden_lattice(std::size_t count);

std::vector<Vector3> axis_directions(std::size_t count);

}  // namespace pbrfit::ltc
