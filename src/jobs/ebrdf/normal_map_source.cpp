#include "pbrfit/jobs/ebrdf/normal_map_source.hpp"

#include <algorithm>

#include "pbrfit/core/error.hpp"
#include "pbrfit/ebrdf/procedural_normal_maps.hpp"
#include "pbrfit/jobs/read_at_key.hpp"
#include "pbrfit/store/image_file.hpp"

namespace pbrfit::jobs::ebrdf {
namespace {

namespace eb = pbrfit::ebrdf;

eb::NormalMap read_normal_map_file(const std::string& path) {
  const store::Rgb8Image image = store::read_rgb8_image(path);
  if (image.width != image.height || !eb::is_power_of_two(image.width) || image.width > max_normal_map_side)
    throw InputError({path}, "a normal map must be square with a power-of-two side of at most " +
                                 std::to_string(max_normal_map_side) + " pixels; this one is " +
                                 std::to_string(image.width) + " x " + std::to_string(image.height));
  return eb::decode_normal_map(image.width, image.pixels);
}

}  // namespace

LoadedNormalMap load_normal_map(const spec::Section& section, std::uint64_t seed) {
  const std::string& name = section.get_string("normal_map");
  const auto& patterns = eb::normal_pattern_names();
  if (std::find(patterns.begin(), patterns.end(), name) != patterns.end()) {
    const auto size = std::size_t(section.get_int("size"));
    if (!eb::is_power_of_two(size)) section.reject("size", "must be a power of two");
    auto map = eb::procedural_normal_map(eb::normal_pattern_from(name), size, seed);
    const std::string side = std::to_string(size);
    return {std::make_shared<const eb::NormalMap>(std::move(map)), name + " (built in, " + side + " x " + side + ")"};
  }
  if (section.given("size")) section.reject("size", "applies to the built-in normal maps only");
  auto map = read_at_key(section, "normal_map", name, [&] { return read_normal_map_file(name); });
  return {std::make_shared<const eb::NormalMap>(std::move(map)), name};
}

}  // namespace pbrfit::jobs::ebrdf
