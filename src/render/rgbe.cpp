#include "rgbe.hpp"

#include <algorithm>
#include <cmath>

namespace pbrfit::render {

std::array<float, 3> rgb_of(const Rgbe& p) {
  if (p[3] == 0) return {0.0f, 0.0f, 0.0f};
  const double scale = std::ldexp(1.0, int(p[3]) - 136);
  return {float((p[0] + 0.5) * scale), float((p[1] + 0.5) * scale), float((p[2] + 0.5) * scale)};
}

Rgbe rgbe_of(const std::array<float, 3>& c) {
  const double largest = std::max({double(c[0]), double(c[1]), double(c[2])});
  if (largest < 1e-32) return {0, 0, 0, 0};
  int exponent = 0;
  std::frexp(largest, &exponent);
  const double scale = std::ldexp(256.0, -exponent);
  const auto mantissa = [&](float v) { return std::uint8_t(std::min(255.0, double(v) * scale)); };
  return {mantissa(c[0]), mantissa(c[1]), mantissa(c[2]), std::uint8_t(exponent + 128)};
}

}  // namespace pbrfit::render
