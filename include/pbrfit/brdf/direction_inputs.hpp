#pragma once
// The inputs a BRDF written as an expression reads for a pair of directions (the vector grammar of genBRDF,
// Brady et al., Figure 4, as dot products): with l = wi (towards the light), v = wo (towards the viewer), h
// the half vector, r = l reflected about the normal n and n = +z,
//   nl = n.l, nv = n.v, nh = n.h, vh = v.h (= l.h), lv = l.v, rv = r.v, hr = h.r, lr = l.r.
// Components .z are the n-products. Shared by the genBRDF search and LTC tables of expression BRDFs.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

inline constexpr std::size_t direction_input_count = 8;

const std::vector<std::string>& direction_input_names();
std::array<double, direction_input_count> direction_inputs(const Vector3& wi, const Vector3& wo);

}  // namespace pbrfit::brdf
