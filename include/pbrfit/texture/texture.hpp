#pragma once
// A table as a texture: the value every encoder of this module (dds.hpp, ktx2.hpp, exr.hpp, radiance_hdr.hpp,
// png16.hpp, npy.hpp, source_code.hpp; format.hpp picks one by name) turns into the bytes of a file.
//
// Contract: texel (x, y, z) of array layer `layer` in mip level `level` has its channel c at
//   values[level_offset(t, level, layer) + ((z * h + y) * w + x) * channels.size() + c]
// where w, h, d = level_width/height/depth(t, level); levels come one after the other (largest first), and
// within a level its layers. Row y = 0 is the first row in memory, and every encoder writes rows in memory
// order, never flipped: texel (x, y) of a file is the value at (x, y). Each encoder header says where its
// format puts y = 0.
//
// validate() throws std::invalid_argument with one line naming what is wrong, and accepts exactly:
// - width, height, depth, layers >= 1 and each below 2^31; depth > 1 (a volume) only with layers == 1;
// - 1 <= levels <= 1 + floor(log2(max(width, height, depth))) (the full chain ends at 1 x 1 x 1);
// - 1 to 4 channels, their names unique, 1 to 64 printable ASCII characters each, no space or comma;
// - values.size() equal to the count the sizes give, which must fit a size_t (each encoder converts values as
//   it says);
// - name, metadata keys and values without NUL characters; metadata keys unique, 1 to 64 printable ASCII
//   characters without spaces, and none of `name`, `channels`, `range:...` (encoders write the name, the
//   channel names and PNG's ranges beside the metadata under those keys).
// level_offset() and the level sizes throw std::out_of_range for a level or layer the texture lacks (and
// std::invalid_argument when the sizes overflow a size_t); they do not validate otherwise.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace pbrfit::texture {

// The stored precision of formats that offer a choice: IEEE 754 binary16 or binary32. Every conversion goes
// double -> float (static_cast<float>), then, for f16, float -> half by Imath's `half` (round to nearest even;
// overflow gives infinity).
enum class Precision { f16, f32 };

struct Texture {
  std::string name;                                           // what the table is (metadata, comments)
  std::size_t width = 1, height = 1, depth = 1;               // texels of mip level 0; depth > 1: a volume
  std::size_t layers = 1;                                     // array layers: 1 is not an array; > 1 needs depth 1
  std::size_t levels = 1;                                     // mip levels, halving each size down to 1
  std::vector<std::string> channels;                          // 1 to 4 channel names, in the order R, G, B, A
  std::vector<double> values;                                 // level, layer, z, y, x, channel (see above)
  std::vector<std::pair<std::string, std::string>> metadata;  // key/value text, where a format can hold it
};

// max(1, size >> level) of each dimension.
std::size_t level_width(const Texture& t, std::size_t level);
std::size_t level_height(const Texture& t, std::size_t level);
std::size_t level_depth(const Texture& t, std::size_t level);
// Values of one layer of a level: width x height x depth x channels of that level.
std::size_t layer_value_count(const Texture& t, std::size_t level);
// The index into values of the first value of (level, layer); level_offset(t, t.levels, 0) is the total count.
std::size_t level_offset(const Texture& t, std::size_t level, std::size_t layer);

void validate(const Texture& t);

}  // namespace pbrfit::texture
