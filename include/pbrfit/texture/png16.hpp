#pragma once
// 16-bit PNG files, written by libpng: gray (1 channel), gray + alpha (2), RGB (3) or RGBA (4), 16 bits per
// sample, not interlaced, zlib's default compression. y = 0 is the first row, the top of the image.
//
// Each channel c is mapped linearly from its own range [min_c, max_c] (its minimum and maximum over the
// texture) to [0, 65535]: q = round((v - min_c) / (max_c - min_c) 65535), rounded to nearest (a constant
// channel stores 0). So min_c is 0 and max_c 65535 exactly, and v' = min_c + q / 65535 (max_c - min_c)
// is within (max_c - min_c) / 131070 of v. The ranges are tEXt chunks "pbrfit:range:CHANNEL" = "MIN MAX"
// (each with 17 significant digits, so they read back as the same doubles); the name, the channel names
// (comma-separated) and the metadata are chunks "pbrfit:name", "pbrfit:channels" and "pbrfit:KEY", tEXt
// when the value is ASCII, else iTXt (UTF-8, uncompressed, no language tag). All text chunks precede the
// image data.
//
// Refused (std::invalid_argument, "png: ..."): what validate() refuses; array layers, volumes and mip levels
// ("png: holds one 2D image, not 6 mip levels"); values that are not finite, the first one named with its
// texel; sizes at or above 2^31 - 1 texels a side. std::runtime_error "png: ..." if libpng fails.
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/texture/texture.hpp"

namespace pbrfit::texture {

struct ChannelRange {
  double min = 0, max = 0;
};

// The range of each channel that encode_png16 maps to [0, 65535].
std::vector<ChannelRange> png16_ranges(const Texture& t);
Bytes encode_png16(const Texture& t);

}  // namespace pbrfit::texture
