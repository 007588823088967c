#include "pbrfit/store/image_file.hpp"

#include <cstring>
#include <memory>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/atomic_file.hpp"
#include "stb_image_decoder.hpp"

namespace pbrfit::store {
namespace {

std::uint32_t big_endian_at(const Bytes& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | std::uint32_t(bytes[at + i]);
  return v;
}

// Every PNG chunk up to IEND must lie within the file: stb_image grows its buffer to a chunk's stated length
// before reading it, so a 74-byte file claiming a 1.9 GB chunk would allocate that much for nothing.
void check_png_chunks(const std::string& path, const Bytes& bytes) {
  static constexpr unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || std::memcmp(bytes.data(), signature, 8) != 0) return;  // not a PNG: TGA or refused
  for (std::size_t at = 8; at + 8 <= bytes.size();) {
    const std::uint64_t length = big_endian_at(bytes, at);
    const std::string type(reinterpret_cast<const char*>(bytes.data()) + at + 4, 4);
    const std::uint64_t left = bytes.size() - at - 8;
    if (length + 4 > left)
      throw InputError({path}, "PNG chunk at byte " + std::to_string(at) + " claims " + std::to_string(length) +
                                   " bytes of data, but only " + std::to_string(left) +
                                   " bytes follow it (truncated or corrupt picture)");
    if (type == "IEND") return;
    at += 12 + std::size_t(length);
  }
}

}  // namespace

Rgb8Image read_rgb8_image(const std::string& path, const std::function<void(std::size_t, std::size_t)>& check_size) {
  const Bytes bytes = read_whole_file(path, max_image_file_bytes);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const int length = static_cast<int>(bytes.size());
  check_png_chunks(path, bytes);
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(data, length, &width, &height, &channels))
    throw InputError({path}, std::string("not a PNG or TGA picture (") + stbi_failure_reason() + ")");
  if (width <= 0 || height <= 0 || std::size_t(width) > max_image_side || std::size_t(height) > max_image_side)
    throw InputError({path}, "picture of " + std::to_string(width) + " x " + std::to_string(height) +
                                 " pixels; at most " + std::to_string(max_image_side) + " per side");
  if (check_size) check_size(std::size_t(width), std::size_t(height));
  std::unique_ptr<unsigned char, void (*)(void*)> pixels(
      stbi_load_from_memory(data, length, &width, &height, &channels, 3), stbi_image_free);
  if (!pixels) throw InputError({path}, std::string("cannot decode the picture (") + stbi_failure_reason() + ")");
  Rgb8Image image{std::size_t(width), std::size_t(height), {}};
  image.pixels.resize(3 * image.width * image.height);
  std::memcpy(image.pixels.data(), pixels.get(), image.pixels.size());
  return image;
}

}  // namespace pbrfit::store
