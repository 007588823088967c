#pragma once
// PNG pictures of renders: 8-bit RGB, from display images (values in [0, 1], as render/display_transform
// makes them from linear renders; the caller applies that transform, as the store does not see engines).
//
// Contract: each value is clamped to [0, 1] and rounded to the nearest of 256 levels (NaN gives 0);
// pictures are encoded by stb_image_write (zlib-compressed, no filtering choice exposed);
// write_png_file replaces PATH atomically (PATH.tmp, then rename; atomic_file.hpp) and throws RunError
// with the operating system's reason when it cannot; an image without pixels, or larger than PNG and
// the encoder allow (width or height >= 2^30), is refused with RunError before anything is written.
#include <cstdint>
#include <string>
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/core/rgb_image.hpp"

namespace pbrfit::store {

// The 8-bit samples, row-major from the top, R G B adjacent.
std::vector<std::uint8_t> png_samples(const RgbImage& display);
Bytes encode_png(const RgbImage& display);
void write_png_file(const std::string& path, const RgbImage& display);

}  // namespace pbrfit::store
