#pragma once
// OpenEXR files, written by the OpenEXR library (3.1) into memory: one scan-line part, ZIP-compressed
// (lossless), line order INCREASING_Y, data and display windows (0, 0) - (width - 1, height - 1).
//
// Channels: one channel is named Y; two to four are R, G, B, A in the texture's channel order; pixel type
// HALF for f16 (Imath's half of each value), FLOAT for f32. The name, the channel names and the metadata
// are string attributes "pbrfit:name", "pbrfit:channels" (comma-separated) and "pbrfit:KEY".
// y = 0, the first scan line of the data window, is the top row (OpenEXR's y grows downwards).
//
// Refused (std::invalid_argument, "exr: ..."): what validate() refuses, array layers, volumes and mip
// levels ("exr: holds one 2D image, not 6 mip levels"), and sizes at or above 2^31 - 1 texels a side.
// std::runtime_error "exr: ..." if the library fails.
#include "pbrfit/core/bytes.hpp"
#include "pbrfit/texture/texture.hpp"

namespace pbrfit::texture {

Bytes encode_exr(const Texture& t, Precision precision);

}  // namespace pbrfit::texture
