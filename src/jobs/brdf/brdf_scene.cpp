#include "pbrfit/jobs/brdf/brdf_scene.hpp"

#include <cstdio>

#include "pbrfit/jobs/read_at_key.hpp"
#include "pbrfit/render/procedural_environments.hpp"
#include "pbrfit/render/radiance_hdr.hpp"
#include "pbrfit/store/atomic_file.hpp"

namespace pbrfit::jobs::brdf {
namespace {

constexpr std::uint64_t max_hdr_bytes = std::uint64_t(1) << 30;

std::string share_text(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", share);
  return text;
}

}  // namespace

spec::Schema scene_schema() {
  spec::Schema s("scene");
  s.string("environment", "interior, sky (built in) or the path of a Radiance .hdr map").defaults_to(std::string("interior"));
  add_sampling_keys(s, 48, 4);
  s.number("keep_share", "the share of the light weight the pruned metric keeps, per channel")
      .range(1e-6, 1.0).defaults_to(0.999);
  return s;
}

void add_sampling_keys(spec::Schema& s, std::int64_t resolution, std::int64_t samples_per_pixel) {
  s.integer("resolution", "pixels across the sphere's render").range(8, 4096).defaults_to(resolution);
  s.integer("samples_per_pixel", "light samples per pixel").range(1, 65536).defaults_to(samples_per_pixel);
}

render::EnvironmentMap scene_environment(const spec::Section& scene) {
  const std::string& name = scene.get_string("environment");
  if (name == "interior") return render::procedural_interior();
  if (name == "sky") return render::procedural_sky();
  const Bytes bytes = read_at_key(scene, "environment", name, [&] { return store::read_whole_file(name, max_hdr_bytes); });
  auto image = render::decode_radiance_hdr(bytes, name);
  try {
    return render::EnvironmentMap(std::move(image));
  } catch (const std::invalid_argument& e) {
    throw InputError({name}, std::string("cannot light a scene: ") + e.what());
  }
}

std::shared_ptr<const BrdfScene> build_scene(const spec::Section& scene, const spec::Section& sampling) {
  const auto environment = scene_environment(scene);
  const std::size_t resolution = std::size_t(sampling.get_int("resolution"));
  const std::size_t spp = std::size_t(sampling.get_int("samples_per_pixel"));
  render::SphereSamples samples(environment, render::SphereView(resolution), spp);
  const render::LightWeightTable weights(samples);
  render::PrunedLightTable table(weights, scene.get_number("keep_share"));
  const auto dropped = table.dropped_share();
  std::map<std::string, std::string> attributes = {
      {"environment", scene.get_string("environment")},
      {"render", std::to_string(resolution) + " x " + std::to_string(resolution) + " pixels, " + std::to_string(spp) +
                     " light samples per pixel"},
      {"metric_cells", std::to_string(table.size()) + " of " + std::to_string(weights.lit_cells()) + " lit MERL cells"},
      {"metric_dropped_share", share_text(dropped[0]) + " " + share_text(dropped[1]) + " " + share_text(dropped[2])}};
  return std::make_shared<const BrdfScene>(BrdfScene{std::move(samples), std::move(table), std::move(attributes)});
}

}  // namespace pbrfit::jobs::brdf
