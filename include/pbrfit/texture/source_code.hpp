#pragma once
// Tables as source code: a C++ header, a GLSL include, an HLSL include or a JavaScript ES module. Every
// generated symbol is the prefix P followed by its name, nothing between (pass "LTC_" for LTC_DATA):
//   P WIDTH, HEIGHT, DEPTH, LAYERS, LEVELS, CHANNELS  the texture's sizes (of level 0)
//   P COUNT                                           the number of values in P DATA
//   P LEVEL_OFFSETS[P LEVELS]                         the index in P DATA of each mip level's first value
//   P DATA[P COUNT]                                   the values, in the texture's order (texture.hpp):
//     DATA[LEVEL_OFFSETS[l] + (((layer * d + z) * h + y) * w + x) * CHANNELS + c], w = max(1, WIDTH >> l), ...
// so y = 0, the first row, comes first. Comments before the symbols hold the name, the sizes, the channel
// names and the metadata, each text quoted with C escapes (\n, \", \xNN: only printable ASCII is written, and
// no comment line ends in a backslash).
//
// - cpp: `#pragma once`, <cstddef>, <cstdint>; `inline constexpr std::size_t` sizes and offsets (C++17);
//   P DATA is `inline constexpr float` (f32; literals like 0.100000001f) or `inline constexpr std::uint16_t`
//   holding the IEEE 754 binary16 bits of Imath's half (f16; literals like 0x3c00).
// - glsl: `#define`d sizes, `const highp int P LEVEL_OFFSETS[P LEVELS] = int[P LEVELS](...)` and
//   `const highp float P DATA[P COUNT] = float[P COUNT](...)`: GLSL ES 3.00 and GLSL 4.50 (no #version; the
//   including shader has it; highp keeps the floats whatever its default precision). GLSL has no half
//   arrays: for f16, P DATA holds the floats equal to the half values (rounded to half, written as floats).
// - hlsl: `#define`d sizes, `static const int P LEVEL_OFFSETS[P LEVELS] = {...}` and
//   `static const float P DATA[P COUNT] = {...}`; for f16 the floats equal to the half values, as for GLSL.
// - js: the layout of three.js's RectAreaLightTexturesLib tables: `export const P WIDTH = 64;` and the other
//   sizes, `export const P LEVEL_OFFSETS = [...]`, and `export const P DATA = new Float32Array([...])` (f32)
//   or `new Uint16Array([...])` of half-float bits (f16), as three.js's DataTexture takes them with FloatType
//   or HalfFloatType.
// Float literals have 9 significant digits, so compilers and JavaScript engines read back the same float.
//
// Refused (std::invalid_argument, "LANGUAGE: ..." with cpp, glsl, hlsl or js): what validate() refuses; a
// prefix that is no plain identifier start (empty; a leading digit or underscore; characters other than
// letters, digits and _; "__"; "gl_" in any case, reserved by GLSL); values that are not finite after the
// conversion to the precision (NaN, infinities; for f16 also magnitudes from 65520 up, which round to
// infinity), the first one named with its texel.
#include <string>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/texture/texture.hpp"

namespace pbrfit::texture {

enum class SourceLanguage { cpp, glsl, hlsl, js };

Bytes encode_source(const Texture& t, Precision precision, SourceLanguage language, const std::string& prefix);

}  // namespace pbrfit::texture
