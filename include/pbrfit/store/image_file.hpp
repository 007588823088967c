#pragma once
// 8-bit RGB pictures read from PNG or TGA files (stb_image; Debian's libstb-dev), such as normal maps.
//
// Contract: read_rgb8_image reads only a regular file of at most max_image_file_bytes, decodes it from
// memory and returns its pixels as R G B (a grey or palette image is expanded, alpha dropped, 16-bit
// channels reduced to 8); anything else throws InputError at the file (line 0) with the reason: not a PNG
// or TGA picture, truncated or corrupt data (a PNG chunk stating more bytes than the file holds is refused
// before stb_image allocates for it), or more than max_image_side pixels on a side.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pbrfit::store {

inline constexpr std::uint64_t max_image_file_bytes = std::uint64_t(64) << 20;
inline constexpr std::size_t max_image_side = 16384;

struct Rgb8Image {
  std::size_t width = 0;
  std::size_t height = 0;
  std::vector<std::uint8_t> pixels;  // row-major from the top, R G B adjacent
};

// `check_size`, when given, sees the header's width and height before any pixel is decoded and may refuse
// them by throwing (a caller with a tighter limit than max_image_side, e.g. normal maps, refuses a large
// picture without its pixels being allocated).
Rgb8Image read_rgb8_image(const std::string& path,
                          const std::function<void(std::size_t width, std::size_t height)>& check_size = {});

}  // namespace pbrfit::store
