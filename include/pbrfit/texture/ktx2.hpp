#pragma once
// Khronos KTX 2.0 files, uncompressed (supercompressionScheme 0), following the KTX 2.0 specification.
//
// Layout: the 12-byte identifier «KTX 20»\r\n\x1A\n; the header: vkFormat (VK_FORMAT_R16_SFLOAT 76,
// R16G16 83, R16G16B16 90, R16G16B16A16 97, R32 100, R32G32 103, R32G32B32 106, R32G32B32A32 109 by
// channels and precision), typeSize (2 or 4: the bytes of one component), pixelWidth, pixelHeight (0 for a
// 1D texture: height and depth 1), pixelDepth (0 unless a volume), layerCount (0 unless an array, else the
// layers), faceCount 1, levelCount (the levels), supercompressionScheme 0; the index (dfdByteOffset and
// dfdByteLength, kvdByteOffset and kvdByteLength, sgdByteOffset and sgdByteLength 0); the level index, one
// entry (byteOffset, byteLength, uncompressedByteLength = byteLength) per level, level 0 first; the Data
// Format Descriptor (dfdTotalSize, then one KHR_DF basic descriptor block: vendorId 0, descriptorType 0,
// versionNumber 2 (1.3), descriptorBlockSize 24 + 16 x channels, colorModel RGBSDA 1, colorPrimaries BT709
// 1, transferFunction LINEAR 1, flags ALPHA_STRAIGHT 0, texelBlockDimension 0 0 0 0, bytesPlane0 the texel
// bytes, the other planes 0; one sample per channel: bitOffset 16 c or 32 c, bitLength 15 or 31 (bits - 1),
// channelType channel id (R 0, G 1, B 2, A 15) | KHR_DF_SAMPLE_DATATYPE_SIGNED 0x40 | FLOAT 0x80,
// samplePosition 0, sampleLower -1.0f (0xBF800000), sampleUpper 1.0f (0x3F800000), as the specification's
// rules for non-compressed formats give them); the key/value data, sorted by key bytewise, each entry its
// keyAndValueByteLength, the key, NUL, the value and NUL, padded to 4 bytes (kvdByteLength counts the
// padding): "KTXorientation" = "r" (1D), "rd" (2D) or "rdi" (3D), "KTXwriter" = "pbrfit", and "pbrfit:KEY"
// for each entry of the name ("pbrfit:name"), the channel names ("pbrfit:channels", comma-separated) and
// the metadata; then the mip levels, from the smallest to the largest (the level index still lists level 0
// first), each level's start aligned to lcm(texel bytes, 4) with zero padding.
// A level holds all its layers together (layer 0 first), each layer its slices z, rows y, texels x, the
// channels interleaved; y = 0 is the first row of a level, at the top in KTX's default "rd" orientation.
//
// Every texture validate() accepts fits; the error messages are validate()'s, starting with "ktx2: ".
#include "pbrfit/core/bytes.hpp"
#include "pbrfit/texture/texture.hpp"

namespace pbrfit::texture {

Bytes encode_ktx2(const Texture& t, Precision precision);

}  // namespace pbrfit::texture
