#include "pbrfit/texture/png16.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <stdexcept>

#include <png.h>

#include "encoding.hpp"

namespace pbrfit::texture {
namespace {

using namespace detail;

struct Output {
  Bytes bytes;
  std::string error;
};

void append(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<Output*>(png_get_io_ptr(png));
  try {
    out->bytes.insert(out->bytes.end(), reinterpret_cast<std::byte*>(data),
                      reinterpret_cast<std::byte*>(data) + length);
  } catch (const std::exception&) {
    png_error(png, "out of memory");
  }
}

void flush(png_structp) {}

void on_error(png_structp png, png_const_charp message) {
  static_cast<Output*>(png_get_error_ptr(png))->error = message;
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

bool ascii(const std::string& text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; });
}

// Everything libpng sees, prepared before it runs (it reports errors by longjmp, past C++ destructors).
struct Image {
  png_uint_32 width = 0, height = 0;
  int color_type = 0;
  std::vector<std::string> keys, values;
  std::vector<png_text> text;
  std::vector<png_byte> samples;  // big-endian 16-bit
  std::vector<png_bytep> rows;
};

// Returns false with out.error set when libpng fails.
bool write_png(Image& image, Output& out) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &out, on_error, on_warning);
  if (png == nullptr) {
    out.error = "cannot create the writer";
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    if (out.error.empty()) out.error = "cannot create the writer";
    return false;
  }
  png_set_write_fn(png, &out, append, flush);
  png_set_IHDR(png, info, image.width, image.height, 16, image.color_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_text(png, info, image.text.data(), int(image.text.size()));
  png_write_info(png, info);
  png_write_image(png, image.rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

void add_text(Image& image, std::string key, std::string value) {
  image.keys.push_back(std::move(key));
  image.values.push_back(std::move(value));
}

}  // namespace

std::vector<ChannelRange> png16_ranges(const Texture& t) {
  const std::size_t channels = t.channels.size();
  std::vector<ChannelRange> ranges(channels);
  for (std::size_t c = 0; c < channels && c < t.values.size(); ++c) ranges[c] = {t.values[c], t.values[c]};
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    ChannelRange& r = ranges[i % channels];
    r.min = std::min(r.min, t.values[i]);
    r.max = std::max(r.max, t.values[i]);
  }
  return ranges;
}

Bytes encode_png16(const Texture& t) {
  check_texture(t, "png");
  require_one_image(t, "png");
  if (t.width >= INT_MAX || t.height >= INT_MAX)
    refuse("png", "holds images below 2^31 - 1 texels a side, not " + std::to_string(t.width) + " x " +
                      std::to_string(t.height));
  for (std::size_t i = 0; i < t.values.size(); ++i)
    if (!std::isfinite(t.values[i]))
      refuse("png", "value " + number(t.values[i]) + " at " + texel_of(t, i) + " is not finite");
  const std::size_t channels = t.channels.size();
  const std::vector<ChannelRange> ranges = png16_ranges(t);
  static constexpr int color_types[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                        PNG_COLOR_TYPE_RGB_ALPHA};
  Image image;
  image.width = png_uint_32(t.width);
  image.height = png_uint_32(t.height);
  image.color_type = color_types[channels - 1];
  for (std::size_t c = 0; c < channels; ++c)
    add_text(image, "pbrfit:range:" + t.channels[c], number(ranges[c].min) + " " + number(ranges[c].max));
  for (const auto& [key, value] : text_entries(t)) add_text(image, "pbrfit:" + key, value);
  for (std::size_t k = 0; k < image.keys.size(); ++k) {
    png_text entry{};
    entry.compression = ascii(image.values[k]) ? PNG_TEXT_COMPRESSION_NONE : PNG_ITXT_COMPRESSION_NONE;
    entry.key = image.keys[k].data();
    entry.text = image.values[k].data();
    if (entry.compression == PNG_TEXT_COMPRESSION_NONE) entry.text_length = image.values[k].size();
    else entry.itxt_length = image.values[k].size();
    image.text.push_back(entry);
  }
  image.samples.resize(t.values.size() * 2);
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    const ChannelRange& r = ranges[i % channels];
    const double span = r.max / 2 - r.min / 2;  // halves: no overflow for ranges wider than the largest double
    const double scaled = span > 0 ? (t.values[i] / 2 - r.min / 2) / span * 65535.0 : 0.0;
    const auto q = std::uint16_t(std::lround(std::clamp(scaled, 0.0, 65535.0)));
    image.samples[2 * i] = png_byte(q >> 8);
    image.samples[2 * i + 1] = png_byte(q & 0xff);
  }
  for (std::size_t y = 0; y < t.height; ++y) image.rows.push_back(image.samples.data() + y * t.width * channels * 2);
  Output out;
  if (!write_png(image, out)) throw std::runtime_error("png: libpng failed: " + out.error);
  return std::move(out.bytes);
}

}  // namespace pbrfit::texture
