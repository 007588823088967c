#pragma once
// Radiance HDR files (RGBE; Ward, "Real Pixels", Graphics Gems II, 1991): the header "#?RADIANCE", comment
// lines "# pbrfit:KEY: "VALUE"" for the name ("pbrfit:name"), the channel names ("pbrfit:channels",
// comma-separated) and the metadata, VALUE quoted with C escapes (\n, \", \xNN, ...), "FORMAT=32-bit_rle_rgbe",
// an empty line, the resolution line "-Y H +X W", then H flat scanlines of W pixels R, G, B, E (4 bytes).
// y = 0 is the first scanline, the top row (the "-Y" of the standard orientation); x = 0 the left column.
// Flat scanlines are unambiguous: a normalized pixel has a mantissa >= 128, so none starts with the bytes
// 2, 2, < 128 that mark a run-length scanline.
//
// Precision is RGBE's own (there is no choice of Precision): channels 1 to 3 are R, G, B (missing ones 0); with
// m = max(R, G, B) in [2^(E-1), 2^E), each component v is stored as floor(v 2^(8-E)) and E + 128; a
// texel with m < 1e-32 is (0, 0, 0, 0). A reader decoding (q 2^(E-8)), as Ward's rgbe.c and stb_image do,
// gets v - 2^(E-8) < v' <= v: an error below m / 128 relative to the texel's largest component; Radiance's
// own (q + 0.5) 2^(E-8) is within half that.
//
// Refused (std::invalid_argument, "hdr: ..."): what validate() refuses; 4 channels ("hdr: holds 3 channels,
// not 4"); array layers, volumes, mip levels ("hdr: holds one 2D image, ..."); values that are negative,
// not finite, or 2^127 and above, the first one named with its texel; header lines over 1000 bytes.
#include "pbrfit/core/bytes.hpp"
#include "pbrfit/texture/texture.hpp"

namespace pbrfit::texture {

Bytes encode_hdr(const Texture& t);

}  // namespace pbrfit::texture
