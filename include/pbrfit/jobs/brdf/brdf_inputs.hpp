#pragma once
// The inputs an analytic BRDF expression reads for a pair of directions (the vector grammar of genBRDF,
// Figure 4, as dot products): with l = wi (towards the light), v = wo (towards the viewer), h the half
// vector, r = l reflected about the normal n and n = +z,
//   nl = n.l, nv = n.v, nh = n.h, vh = v.h (= l.h), lv = l.v, rv = r.v, hr = h.r, lr = l.r,
// then the parameters p0..p3 (fitted per material and channel). Components .z are the n-products.
#include <array>
#include <string>
#include <vector>

#include "pbrfit/ltc/vector.hpp"

namespace pbrfit::jobs::brdf {

inline constexpr std::size_t brdf_input_count = 8;
inline constexpr std::size_t brdf_parameter_count = 4;

const std::vector<std::string>& brdf_input_names();
const std::vector<std::string>& brdf_parameter_names();
std::array<double, brdf_input_count> brdf_inputs(const ltc::Vector3& wi, const ltc::Vector3& wo);

}  // namespace pbrfit::jobs::brdf
