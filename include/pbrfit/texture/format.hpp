#pragma once
// The formats of the texture module by name, for callers that choose one at run time (a command line).
//
// Names and file extensions: dds .dds, ktx2 .ktx2, exr .exr, hdr .hdr, png .png (16-bit, png16.hpp),
// npy .npy, cpp .hpp, glsl .glsl, hlsl .hlsl, js .js. encode() calls the format's encoder (the headers
// beside this one say what each writes and refuses); hdr and png have one precision of their own (RGBE,
// 16-bit integers) and ignore options.precision; options.prefix is for the source formats only (cpp,
// glsl, hlsl, js) and ignored by the others. Every refusal is std::invalid_argument starting with the
// format's name.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/texture/texture.hpp"

namespace pbrfit::texture {

enum class Format { dds, ktx2, exr, hdr, png, npy, cpp, glsl, hlsl, js };

struct EncodeOptions {
  Precision precision = Precision::f32;
  std::string prefix;  // the source formats' symbol prefix
};

std::string_view format_name(Format format);
std::string_view file_extension(Format format);  // with the dot: ".ktx2"
std::optional<Format> format_named(std::string_view name);
const std::vector<Format>& all_formats();
Bytes encode(const Texture& t, Format format, const EncodeOptions& options = {});

}  // namespace pbrfit::texture
