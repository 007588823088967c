#pragma once
// The image errors of genBRDF's tables (Brady et al. 2014, section 4), between two display images
// (display_transform.hpp) of the same size, over the pixels a mask marks (mask[p] != 0: the sphere):
//  - rgb_rms_error: the root mean square over the masked pixels and the three channels of the difference;
//  - ssim: the mean structural similarity (Wang et al. 2004) of the luminances (Rec. 709 weights of the
//    display values), with an 11 x 11 Gaussian window of sigma 1.5 (normalized), C1 = 0.01^2 and
//    C2 = 0.03^2 (dynamic range 1), averaged over the masked pixels as window centres. Outside the image
//    the window sees black, the background of the renders.
//
// Invariants: identical images give error 0 and SSIM 1; both are symmetric in their images; sizes that
// differ, a mask of the wrong length or one marking no pixel throw std::invalid_argument.
#include <cstdint>
#include <span>

#include "pbrfit/core/rgb_image.hpp"

namespace pbrfit::render {

double rgb_rms_error(const RgbImage& a, const RgbImage& b, std::span<const std::uint8_t> mask);
double ssim(const RgbImage& a, const RgbImage& b, std::span<const std::uint8_t> mask);

struct ImageComparison {
  double rgb_l2 = 0.0;          // rgb_rms_error
  double one_minus_ssim = 0.0;  // 1 - ssim
};

// Both errors of two linear renders shown at `exposure`.
ImageComparison compare_renders(const RgbImage& reference, const RgbImage& test, std::span<const std::uint8_t> mask,
                                double exposure = 1.0);

}  // namespace pbrfit::render
