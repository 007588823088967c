#pragma once
// From linear radiance to display values, as renders are shown and compared: scale by `exposure`, clamp
// to [0, 1], encode with the sRGB transfer function (IEC 61966-2-1: 12.92 v below 0.0031308, else
// 1.055 v^(1/2.4) - 0.055).
//
// Invariants: every display value is in [0, 1]; 0 maps to 0 and everything >= 1/exposure to 1; the
// transform is monotonic; NaN displays as 0; the image size is kept.
#include "pbrfit/core/rgb_image.hpp"

namespace pbrfit::render {

double srgb_encode(double linear);  // for linear in [0, 1]
double display_value(double linear, double exposure = 1.0);
RgbImage display(const RgbImage& linear, double exposure = 1.0);

}  // namespace pbrfit::render
