#pragma once
// The scene of genBRDF's metric and renders (Brady et al., sections 3.4-3.5): a sphere seen by the
// orthographic camera of render/sphere_view.hpp, lit by an environment (a built-in procedural one or a
// Radiance .hdr file), its light samples stored once, and the pruned light weight table of the metric.
//
// Invariants: built once per process from the job's `scene` section and shared read-only by every compute
// thread; a pure function of that section (and the .hdr file's bytes). attributes() describe it for the
// result file: environment, resolution, samples, lit and kept cells and the dropped share of the weight.
#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "pbrfit/render/environment_map.hpp"
#include "pbrfit/render/pruned_light_table.hpp"
#include "pbrfit/render/sphere_samples.hpp"
#include "pbrfit/spec/keys.hpp"

namespace pbrfit::jobs::brdf {

struct BrdfScene {
  render::SphereSamples samples;
  render::PrunedLightTable table;
  std::map<std::string, std::string> attributes;
};

// The job's `scene` section as written.
struct SceneSection {
  spec::Located<std::string> environment;  // interior, sky or the path of a .hdr file
  std::size_t resolution = 48, samples_per_pixel = 4;
  double keep_share = 0.999;
};
const spec::Keys<SceneSection>& scene_keys();

// `resolution` and `samples_per_pixel` with these defaults, filling the members of those names.
template <class Holder>
void add_sampling_keys(spec::Keys<Holder>& k, std::int64_t resolution, std::int64_t samples_per_pixel) {
  k.integer("resolution", "pixels across the sphere's render", &Holder::resolution).range(8, 4096).defaults_to(resolution);
  k.integer("samples_per_pixel", "light samples per pixel", &Holder::samples_per_pixel)
      .range(1, 65536)
      .defaults_to(samples_per_pixel);
}

// The environment a `scene.environment` value names: "interior", "sky" or the path of a .hdr file
// (InputError at the key when it cannot be read or decoded).
render::EnvironmentMap scene_environment(const spec::Located<std::string>& environment);
// The scene of `scene` (environment, keep_share) rendered at `resolution` and `samples_per_pixel` (the
// scene's own for the search's metric; the `evaluate` section's for the finer renders and fits).
std::shared_ptr<const BrdfScene> build_scene(const SceneSection& scene, std::size_t resolution,
                                             std::size_t samples_per_pixel);

}  // namespace pbrfit::jobs::brdf
