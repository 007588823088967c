#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "pbrfit/render/radiance_hdr.hpp"
#include "rgbe.hpp"

namespace pbrfit::render {
namespace {

constexpr std::size_t longest_run = 127, longest_literal = 128, shortest_run = 4;

void put(Bytes& out, std::size_t byte) { out.push_back(std::byte(byte)); }

void put_text(Bytes& out, const std::string& text) {
  for (char c : text) put(out, std::uint8_t(c));
}

// How many bytes from `at` equal the one there, at most longest_run.
std::size_t run_at(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  std::size_t run = 1;
  while (run < longest_run && at + run < bytes.size() && bytes[at + run] == bytes[at]) ++run;
  return run;
}

void put_literals(Bytes& out, const std::vector<std::uint8_t>& bytes, std::size_t begin, std::size_t end) {
  while (begin < end) {
    const std::size_t count = std::min(longest_literal, end - begin);
    put(out, count);
    for (std::size_t i = 0; i < count; ++i) put(out, bytes[begin + i]);
    begin += count;
  }
}

// One component of a scanline as runs: repeats of at least shortest_run bytes, literals between them.
void put_runs(Bytes& out, const std::vector<std::uint8_t>& bytes) {
  for (std::size_t at = 0; at < bytes.size();) {
    std::size_t start = at, run = 0;
    while (start < bytes.size() && (run = run_at(bytes, start)) < shortest_run) start += run;
    put_literals(out, bytes, at, start);
    if (start == bytes.size()) return;
    put(out, 128 + run);
    put(out, bytes[start]);
    at = start + run;
  }
}

std::vector<Rgbe> scanline(const RgbImage& image, std::size_t row) {
  std::vector<Rgbe> pixels(image.width());
  for (std::size_t column = 0; column < image.width(); ++column) pixels[column] = rgbe_of(image.pixel(column, row));
  return pixels;
}

void put_run_length(Bytes& out, const std::vector<Rgbe>& pixels) {
  put(out, 2);
  put(out, 2);
  put(out, pixels.size() >> 8);
  put(out, pixels.size() & 0xff);
  std::vector<std::uint8_t> component(pixels.size());
  for (std::size_t k = 0; k < 4; ++k) {
    for (std::size_t i = 0; i < pixels.size(); ++i) component[i] = pixels[i][k];
    put_runs(out, component);
  }
}

void put_flat(Bytes& out, const std::vector<Rgbe>& pixels) {
  for (const Rgbe& p : pixels)
    for (std::uint8_t component : p) put(out, component);
}

void check_encodable(const RgbImage& image) {
  if (image.pixels() == 0) throw std::invalid_argument("a Radiance HDR picture needs at least one pixel");
  for (float v : image.values())
    if (!std::isfinite(v) || v < 0.0f || v >= 0x1.0p127f)
      throw std::invalid_argument("Radiance HDR values must be finite, >= 0 and below 2^127");
}

}  // namespace

Bytes encode_radiance_hdr(const RgbImage& image, HdrScanlines scanlines) {
  check_encodable(image);
  Bytes out;
  put_text(out, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(image.height()) + " +X " +
                    std::to_string(image.width()) + "\n");
  const bool runs = scanlines == HdrScanlines::run_length && run_length_width(image.width());
  for (std::size_t row = 0; row < image.height(); ++row) {
    const std::vector<Rgbe> pixels = scanline(image, row);
    if (runs) put_run_length(out, pixels);
    else put_flat(out, pixels);
  }
  return out;
}

}  // namespace pbrfit::render
