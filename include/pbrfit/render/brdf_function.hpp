#pragma once
// A BRDF as a callable on a pair of unit directions in the local shading frame (normal +z; wo towards
// the viewer), returning its RGB value (not multiplied by the cosine).
#include <functional>

#include "pbrfit/geometry/vector.hpp"
#include "pbrfit/render/rgb.hpp"

namespace pbrfit::render {

using BrdfFunction = std::function<Rgb(const Vector3& wi, const Vector3& wo)>;

}  // namespace pbrfit::render
