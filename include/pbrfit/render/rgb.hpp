#pragma once
// Linear RGB triples in double precision (Rec. 709 primaries), the colour type of the render engines.
//
// Invariant: luminance is the Rec. 709 / sRGB weighting, so a grey (v, v, v) has luminance v.
#include <array>

namespace pbrfit::render {

using Rgb = std::array<double, 3>;

inline constexpr Rgb luminance_weights = {0.2126, 0.7152, 0.0722};

inline double luminance(const Rgb& c) {
  return luminance_weights[0] * c[0] + luminance_weights[1] * c[1] + luminance_weights[2] * c[2];
}

inline Rgb to_rgb(const std::array<float, 3>& c) { return {double(c[0]), double(c[1]), double(c[2])}; }

}  // namespace pbrfit::render
