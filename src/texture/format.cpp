#include "pbrfit/texture/format.hpp"

#include "pbrfit/texture/dds.hpp"
#include "pbrfit/texture/exr.hpp"
#include "pbrfit/texture/ktx2.hpp"
#include "pbrfit/texture/npy.hpp"
#include "pbrfit/texture/png16.hpp"
#include "pbrfit/texture/radiance_hdr.hpp"
#include "pbrfit/texture/source_code.hpp"

namespace pbrfit::texture {
namespace {

struct Entry {
  Format format;
  std::string_view name, extension;
};

constexpr Entry entries[] = {{Format::dds, "dds", ".dds"},    {Format::ktx2, "ktx2", ".ktx2"},
                             {Format::exr, "exr", ".exr"},    {Format::hdr, "hdr", ".hdr"},
                             {Format::png, "png", ".png"},    {Format::npy, "npy", ".npy"},
                             {Format::cpp, "cpp", ".hpp"},    {Format::glsl, "glsl", ".glsl"},
                             {Format::hlsl, "hlsl", ".hlsl"}, {Format::js, "js", ".js"}};

const Entry& entry(Format format) {
  for (const Entry& e : entries)
    if (e.format == format) return e;
  return entries[0];
}

}  // namespace

std::string_view format_name(Format format) { return entry(format).name; }
std::string_view file_extension(Format format) { return entry(format).extension; }

std::optional<Format> format_named(std::string_view name) {
  for (const Entry& e : entries)
    if (e.name == name) return e.format;
  return std::nullopt;
}

const std::vector<Format>& all_formats() {
  static const std::vector<Format> formats = [] {
    std::vector<Format> all;
    for (const Entry& e : entries) all.push_back(e.format);
    return all;
  }();
  return formats;
}

Bytes encode(const Texture& t, Format format, const EncodeOptions& options) {
  switch (format) {
    case Format::dds: return encode_dds(t, options.precision);
    case Format::ktx2: return encode_ktx2(t, options.precision);
    case Format::exr: return encode_exr(t, options.precision);
    case Format::hdr: return encode_hdr(t);
    case Format::png: return encode_png16(t);
    case Format::npy: return encode_npy(t, options.precision);
    case Format::cpp: return encode_source(t, options.precision, SourceLanguage::cpp, options.prefix);
    case Format::glsl: return encode_source(t, options.precision, SourceLanguage::glsl, options.prefix);
    case Format::hlsl: return encode_source(t, options.precision, SourceLanguage::hlsl, options.prefix);
    case Format::js: return encode_source(t, options.precision, SourceLanguage::js, options.prefix);
  }
  return {};
}

}  // namespace pbrfit::texture
