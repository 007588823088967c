#include "pbrfit/jobs/ebrdf/normal_map_source.hpp"

#include <algorithm>

#include "pbrfit/core/error.hpp"
#include "pbrfit/ebrdf/procedural_normal_maps.hpp"
#include "pbrfit/store/image_file.hpp"

namespace pbrfit::jobs::ebrdf {
namespace {

namespace eb = pbrfit::ebrdf;

eb::NormalMap read_normal_map_file(const std::string& path) {
  // The shape is checked from the picture's header, before its pixels are decoded.
  const store::Rgb8Image image = store::read_rgb8_image(path, [&](std::size_t width, std::size_t height) {
    if (width != height || !eb::is_power_of_two(width) || width > max_normal_map_side)
      throw InputError({path}, "a normal map must be square with a power-of-two side of at most " +
                                   std::to_string(max_normal_map_side) + " pixels; this one is " +
                                   std::to_string(width) + " x " + std::to_string(height));
  });
  return eb::decode_normal_map(image.width, image.pixels);
}

}  // namespace

bool is_builtin_normal_map(const std::string& name) {
  const auto& patterns = eb::normal_pattern_names();
  return std::find(patterns.begin(), patterns.end(), name) != patterns.end();
}

LoadedNormalMap builtin_normal_map(const std::string& name, std::size_t size, std::uint64_t seed) {
  auto map = eb::procedural_normal_map(eb::normal_pattern_from(name), size, seed);
  const std::string side = std::to_string(size);
  return {std::make_shared<const eb::NormalMap>(std::move(map)), name + " (built in, " + side + " x " + side + ")"};
}

LoadedNormalMap normal_map_file(const std::string& path) {
  return {std::make_shared<const eb::NormalMap>(read_normal_map_file(path)), path};
}

}  // namespace pbrfit::jobs::ebrdf
