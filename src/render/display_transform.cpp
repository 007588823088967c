#include "pbrfit/render/display_transform.hpp"

#include <algorithm>
#include <cmath>

namespace pbrfit::render {

double srgb_encode(double v) {
  if (v >= 1.0) return 1.0;
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

double display_value(double linear, double exposure) {
  const double scaled = linear * exposure;
  return std::isnan(scaled) ? 0.0 : std::clamp(srgb_encode(std::clamp(scaled, 0.0, 1.0)), 0.0, 1.0);
}

RgbImage display(const RgbImage& linear, double exposure) {
  RgbImage shown = linear;
  for (float& v : shown.values()) v = float(display_value(v, exposure));
  return shown;
}

}  // namespace pbrfit::render
