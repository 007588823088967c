#pragma once
// What a genBRDF expression reads: the direction inputs of brdf/direction_inputs.hpp (nl, nv, nh, vh, lv,
// rv, hr, lr), then the parameters p0..p3 (fitted per material and channel).
#include <cstddef>
#include <string>
#include <vector>

#include "pbrfit/brdf/direction_inputs.hpp"

namespace pbrfit::jobs::brdf {

inline constexpr std::size_t brdf_input_count = pbrfit::brdf::direction_input_count;
inline constexpr std::size_t brdf_parameter_count = 4;

const std::vector<std::string>& brdf_parameter_names();

}  // namespace pbrfit::jobs::brdf
