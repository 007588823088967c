#pragma once
// Radiance HDR pictures (`.hdr`, RGBE; Ward 1991, the format of Radiance's color.c), decoded from and
// encoded to bytes. A file is a header of text lines - the first `#?RADIANCE` or `#?RGBE`, then
// variables such as `FORMAT=32-bit_rle_rgbe` - ended by an empty line; a resolution line, of which only
// the standard orientation `-Y H +X W` (rows from the top, columns from the left) is accepted; then H
// scanlines, each either flat (W pixels of 4 bytes R, G, B, E) or new-style run-length encoded (bytes
// 2, 2, W / 256, W % 256, then each of the 4 components in turn as runs: a count above 128 repeats the
// next byte count - 128 times, a count of 1..128 is followed by that many literal bytes).
// A pixel (R, G, B, E) is (R + 0.5, G + 0.5, B + 0.5) 2^(E - 136), or black when E = 0.
//
// Decoding invariants: any bytes give either an image or pbrfit::InputError naming the file (`name`,
// line 0) with "at byte N" in its message; work and memory are bounded by the input's size, so hostile
// dimensions are refused before anything is allocated: at most max_hdr_texels texels, and no more than
// the remaining bytes could hold. FORMAT must be 32-bit_rle_rgbe when given (XYZE is refused); other
// header variables (EXPOSURE, PRIMARIES, ...) and bytes after the last scanline are ignored, as are
// old-style (1, 1, 1, n) repeat pixels, which read as the colours they spell.
// Encoding invariants: values finite, >= 0 and below 2^127 (std::invalid_argument otherwise); each
// channel keeps 8 bits relative to the pixel's largest (values below 1e-32 of it read back as 0);
// decode(encode(image)) re-encodes to the same bytes. Run-length scanlines need 8 <= W <= 32767; other
// widths are written flat.
#include <cstddef>
#include <span>
#include <string>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/core/rgb_image.hpp"

namespace pbrfit::render {

inline constexpr std::size_t max_hdr_texels = std::size_t(1) << 26;  // 64 Mi

RgbImage decode_radiance_hdr(std::span<const std::byte> bytes, const std::string& name);

enum class HdrScanlines { run_length, flat };

Bytes encode_radiance_hdr(const RgbImage& image, HdrScanlines scanlines = HdrScanlines::run_length);

}  // namespace pbrfit::render
