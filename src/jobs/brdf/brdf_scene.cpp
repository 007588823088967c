#include "pbrfit/jobs/brdf/brdf_scene.hpp"

#include <cstdio>

#include "pbrfit/jobs/read_named_file.hpp"
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

const spec::Keys<SceneSection>& scene_keys() {
  static const spec::Keys<SceneSection> keys = [] {
    spec::Keys<SceneSection> k("scene");
    k.string("environment", "interior, sky (built in) or the path of a Radiance .hdr map", &SceneSection::environment)
        .defaults_to(std::string("interior"));
    add_sampling_keys(k, 48, 4);
    k.number("keep_share", "the share of the light weight the pruned metric keeps, per channel", &SceneSection::keep_share)
        .range(1e-6, 1.0)
        .defaults_to(0.999);
    return k;
  }();
  return keys;
}

render::EnvironmentMap scene_environment(const spec::Located<std::string>& environment) {
  const std::string& name = environment.value;
  if (name == "interior") return render::procedural_interior();
  if (name == "sky") return render::procedural_sky();
  Bytes bytes;
  if (const auto problem = read_named_file(name, [&] { bytes = store::read_whole_file(name, max_hdr_bytes); });
      !problem.empty())
    environment.reject(problem);
  auto image = render::decode_radiance_hdr(bytes, name);
  try {
    return render::EnvironmentMap(std::move(image));
  } catch (const std::invalid_argument& e) {
    throw InputError({name}, std::string("cannot light a scene: ") + e.what());
  }
}

std::shared_ptr<const BrdfScene> build_scene(const SceneSection& scene, std::size_t resolution, std::size_t spp) {
  const auto environment = scene_environment(scene.environment);
  render::SphereSamples samples(environment, render::SphereView(resolution), spp);
  const render::LightWeightTable weights(samples);
  render::PrunedLightTable table(weights, scene.keep_share);
  const auto dropped = table.dropped_share();
  std::map<std::string, std::string> attributes = {
      {"environment", scene.environment.value},
      {"render", std::to_string(resolution) + " x " + std::to_string(resolution) + " pixels, " + std::to_string(spp) +
                     " light samples per pixel"},
      {"metric_cells", std::to_string(table.size()) + " of " + std::to_string(weights.lit_cells()) + " lit MERL cells"},
      {"metric_dropped_share", share_text(dropped[0]) + " " + share_text(dropped[1]) + " " + share_text(dropped[2])}};
  return std::make_shared<const BrdfScene>(BrdfScene{std::move(samples), std::move(table), std::move(attributes)});
}

}  // namespace pbrfit::jobs::brdf
