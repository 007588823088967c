#pragma once
// The four numbers a shader reads per texel for an isotropic LTC: the published ltc_1 texture convention
// of the 2017 revision of the reference code (ltc_code, fitLTC.cpp packTab). For M whose (0,1), (1,0),
// (1,2) and (2,1) entries are 0, the inverse is divided by its middle entry, leaving four variable entries:
//   shader_form(M) = (Minv00, Minv20, Minv02, Minv22) / Minv11      (row, column indices)
// and a shader rebuilds, row-major,
//   Minv = | x  0  z |
//          | 0  1  0 |
//          | y  0  w |
// (in GLSL: mat3(vec3(x, 0, y), vec3(0, 1, 0), vec3(z, 0, w)), columns).
//
// Invariants: inverse_from_shader_form(shader_form(M)) = M^-1 / Minv11; matrix_from_shader_form returns its
// inverse, which is M scaled so that its middle entry is 1 (the same LTC). shader_form throws
// std::invalid_argument if M is singular or M's inverse has a zero middle entry.
#include <array>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

using ShaderForm = std::array<double, 4>;

ShaderForm shader_form(const Matrix3& m);

Matrix3 inverse_from_shader_form(const ShaderForm& form);

Matrix3 matrix_from_shader_form(const ShaderForm& form);

}  // namespace pbrfit::ltc
