#pragma once
// DirectDraw Surface files with the DX10 header extension (Microsoft's "Programming Guide for DDS"):
// "DDS ", DDS_HEADER (124 bytes), DDS_HEADER_DXT10 (20 bytes), then the texels.
//
// DDS_HEADER: dwSize 124; dwFlags DDSD_CAPS | DDSD_HEIGHT | DDSD_WIDTH | DDSD_PIXELFORMAT | DDSD_PITCH
// (0x100f), plus DDSD_MIPMAPCOUNT (0x20000) with more than one level and DDSD_DEPTH (0x800000) for a
// volume; dwHeight, dwWidth of level 0; dwPitchOrLinearSize the bytes of one row of level 0; dwDepth the
// depth of a volume, else 0; dwMipMapCount the levels when DDSD_MIPMAPCOUNT is set, else 0; ddspf: dwSize
// 32, dwFlags DDPF_FOURCC (0x4), dwFourCC "DX10", bit count and masks 0; dwCaps DDSCAPS_TEXTURE (0x1000),
// plus DDSCAPS_COMPLEX (0x8) when the file holds more than one surface (mips, array layers, a volume) and
// DDSCAPS_MIPMAP (0x400000) with mips; dwCaps2 DDSCAPS2_VOLUME (0x200000) for a volume; the rest 0.
// DDS_HEADER_DXT10: dxgiFormat R32_FLOAT 41, R32G32_FLOAT 16, R32G32B32_FLOAT 6, R32G32B32A32_FLOAT 2, or
// for f16 R16_FLOAT 54, R16G16_FLOAT 34, R16G16B16A16_FLOAT 10: DXGI has no 3-channel half format, so a
// 3-channel f16 texture is widened to RGBA with A = 1.0 in every texel; resourceDimension TEXTURE1D (2)
// when height and depth are 1, TEXTURE3D (4) for a volume, else TEXTURE2D (3); miscFlag 0 (no cube
// maps); arraySize the layers (1 for a volume or a single texture); miscFlags2 the alpha mode:
// DDS_ALPHA_MODE_CUSTOM (4, alpha is a fourth data channel) with 4 channels, DDS_ALPHA_MODE_OPAQUE (3) for
// the widened 3-channel half texture, else DDS_ALPHA_MODE_UNKNOWN (0).
// Texels: for each array layer, its mip levels from the largest; each level its slices z = 0, 1, ..., each
// slice its rows y = 0, 1, ... (y = 0, the first row in the file, is the top row in Direct3D's convention),
// each row x = 0, 1, ..., channels interleaved R, G, B, A; little-endian, no padding.
//
// Every texture validate() accepts fits; the error messages are validate()'s, starting with "dds: ".
#include "pbrfit/core/bytes.hpp"
#include "pbrfit/texture/texture.hpp"

namespace pbrfit::texture {

Bytes encode_dds(const Texture& t, Precision precision);

}  // namespace pbrfit::texture
