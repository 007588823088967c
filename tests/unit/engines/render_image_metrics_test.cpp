// The display transform and the image errors of the paper's tables (RGB L2, SSIM) on hand-computed cases.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "pbrfit/render/display_transform.hpp"
#include "pbrfit/render/image_metrics.hpp"

using namespace pbrfit::render;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using pbrfit::RgbImage;

namespace {

constexpr double c1 = 1e-4, c2 = 9e-4;

// Marks the pixels at least `margin` from every edge.
std::vector<std::uint8_t> inner_mask(std::size_t size, std::size_t margin) {
  std::vector<std::uint8_t> mask(size * size, 0);
  for (std::size_t y = margin; y + margin < size; ++y)
    for (std::size_t x = margin; x + margin < size; ++x) mask[y * size + x] = 1;
  return mask;
}

RgbImage grey(std::size_t size, float v) { return RgbImage(size, size, {v, v, v}); }

// The centre weight of the normalized 11 x 11 Gaussian of sigma 1.5.
double centre_weight() {
  double sum = 0.0;
  for (int i = -5; i <= 5; ++i) sum += std::exp(-i * i / 4.5);
  return 1.0 / (sum * sum);
}

}  // namespace

TEST_CASE("the display transform: exposure, clamp to [0, 1], sRGB encoding") {
  CHECK(display_value(0.0) == 0.0);
  CHECK(display_value(1.0) == 1.0);
  CHECK(display_value(7.0) == 1.0);
  CHECK(display_value(-1.0) == 0.0);
  CHECK(display_value(std::nan("")) == 0.0);
  CHECK_THAT(display_value(0.002), WithinAbs(12.92 * 0.002, 1e-15));
  CHECK_THAT(display_value(0.5), WithinAbs(1.055 * std::pow(0.5, 1.0 / 2.4) - 0.055, 1e-15));
  CHECK_THAT(display_value(0.5), WithinAbs(0.735357, 1e-6));
  CHECK(display_value(0.25, 2.0) == display_value(0.5));
  CHECK_THAT(srgb_encode(0.0031308), WithinAbs(srgb_encode(std::nextafter(0.0031308, 1.0)), 1e-7));  // pieces meet
  const RgbImage shown = display(RgbImage(2, 1, {0.5f, 2.0f, 0.0f}), 1.0);
  CHECK(shown.width() == 2);
  CHECK(shown.pixel(1)[1] == 1.0f);
}

TEST_CASE("the RGB L2 error is the root mean square over the masked pixels and channels") {
  const auto mask = inner_mask(8, 1);  // 36 pixels
  CHECK(rgb_rms_error(grey(8, 0.4f), grey(8, 0.4f), mask) == 0.0);
  CHECK_THAT(rgb_rms_error(grey(8, 0.4f), grey(8, 0.5f), mask), WithinAbs(0.1, 1e-7));
  RgbImage one_off = grey(8, 0.4f);
  one_off.set(3, 3, {0.7f, 0.4f, 0.4f});
  one_off.set(0, 0, {1.0f, 1.0f, 1.0f});  // outside the mask: not counted
  CHECK_THAT(rgb_rms_error(grey(8, 0.4f), one_off, mask), WithinAbs(std::sqrt(0.09 / (3.0 * 36.0)), 1e-7));
  CHECK_THROWS_AS(rgb_rms_error(grey(8, 0.4f), grey(7, 0.4f), mask), std::invalid_argument);
  CHECK_THROWS_AS(rgb_rms_error(grey(8, 0.4f), grey(8, 0.4f), std::vector<std::uint8_t>(64, 0)), std::invalid_argument);
  CHECK_THROWS_AS(rgb_rms_error(grey(8, 0.4f), grey(8, 0.4f), std::vector<std::uint8_t>(3, 1)), std::invalid_argument);
}

TEST_CASE("SSIM: 1 for identical images, the luminance term for a constant offset, a known single-pixel case") {
  RgbImage textured(24, 24);
  for (std::size_t p = 0; p < textured.pixels(); ++p) textured.set(p, {float(p % 5) / 5.0f, 0.3f, float(p % 3) / 3.0f});
  const auto all = std::vector<std::uint8_t>(24 * 24, 1);
  CHECK_THAT(ssim(textured, textured, all), WithinAbs(1.0, 1e-12));
  const auto inner = inner_mask(24, 5);  // windows entirely inside the image
  const double a = 0.3, b = 0.5;
  CHECK_THAT(ssim(grey(24, float(a)), grey(24, float(b)), inner),
             WithinRel((2 * a * b + c1) / (a * a + b * b + c1), 1e-6));
  // One pixel brighter by d at the centre of a grey 0.5 field, measured at that pixel only:
  // mean_b = 0.5 + g d, var_b = g (1 - g) d^2, covariance 0.
  RgbImage bump = grey(24, 0.5f);
  const float d = 0.25f;
  bump.set(12, 12, {0.5f + d, 0.5f + d, 0.5f + d});
  std::vector<std::uint8_t> centre(24 * 24, 0);
  centre[12 * 24 + 12] = 1;
  const double g = centre_weight(), mean_b = 0.5 + g * d, var_b = g * (1 - g) * d * d;
  const double expected = (2 * 0.5 * mean_b + c1) * c2 / ((0.25 + mean_b * mean_b + c1) * (var_b + c2));
  CHECK_THAT(ssim(grey(24, 0.5f), bump, centre), WithinRel(expected, 1e-6));
  CHECK_THAT(ssim(bump, grey(24, 0.5f), centre), WithinRel(expected, 1e-6));
  CHECK(ssim(grey(24, 0.5f), bump, all) < 1.0);
}

TEST_CASE("comparing renders displays them first and reports L2 and 1 - SSIM") {
  const RgbImage linear(16, 16, {0.2f, 0.3f, 0.4f});
  const auto all = std::vector<std::uint8_t>(256, 1);
  const ImageComparison same = compare_renders(linear, linear, all);
  CHECK(same.rgb_l2 == 0.0);
  CHECK_THAT(same.one_minus_ssim, WithinAbs(0.0, 1e-12));
  const ImageComparison brighter = compare_renders(linear, RgbImage(16, 16, {0.4f, 0.6f, 0.8f}), all, 1.0);
  const double expected = std::sqrt((std::pow(display_value(0.4) - display_value(0.2), 2) +
                                     std::pow(display_value(0.6) - display_value(0.3), 2) +
                                     std::pow(display_value(0.8) - display_value(0.4), 2)) / 3.0);
  CHECK_THAT(brighter.rgb_l2, WithinRel(expected, 1e-6));
  CHECK(brighter.one_minus_ssim > 0.0);
}
