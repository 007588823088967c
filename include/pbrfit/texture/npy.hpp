#pragma once
// NumPy .npy files, format version 1.0 (NumPy's NEP 1): the magic "\x93NUMPY", bytes 1 and 0, the header
// length (little-endian 16 bits), then the header "{'descr': '<f4', 'fortran_order': False, 'shape': (...), }"
// ('<f2' for f16) padded with spaces and a final newline so that the data starts at a multiple of 64 bytes,
// then the values in C order, little-endian.
// Shape: (layers, depth, height, width, channels) with the layers dimension left out when there is one layer
// and the depth left out when it is 1; height, width and channels are always there. So array[y][x][c] is
// texel (x, y), and y = 0, the first row, comes first. The format holds no name or metadata.
//
// Refused (std::invalid_argument, "npy: ..."): what validate() refuses, and mip levels ("npy: holds one mip
// level, not 6").
#include "pbrfit/core/bytes.hpp"
#include "pbrfit/texture/texture.hpp"

namespace pbrfit::texture {

Bytes encode_npy(const Texture& t, Precision precision);

}  // namespace pbrfit::texture
