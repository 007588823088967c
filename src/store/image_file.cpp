#include "pbrfit/store/image_file.hpp"

#include <cstring>
#include <memory>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/atomic_file.hpp"
#include "stb_image_decoder.hpp"

namespace pbrfit::store {

Rgb8Image read_rgb8_image(const std::string& path, const std::function<void(std::size_t, std::size_t)>& check_size) {
  const Bytes bytes = read_whole_file(path, max_image_file_bytes);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const int length = static_cast<int>(bytes.size());
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
