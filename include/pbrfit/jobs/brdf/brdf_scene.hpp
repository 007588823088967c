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
#include "pbrfit/spec/schema.hpp"

namespace pbrfit::jobs::brdf {

struct BrdfScene {
  render::SphereSamples samples;
  render::PrunedLightTable table;
  std::map<std::string, std::string> attributes;
};

// The environment a `scene.environment` value names: "interior", "sky" or the path of a .hdr file
// (InputError at the key when it cannot be read or decoded).
render::EnvironmentMap scene_environment(const spec::Section& scene);
// The scene of `scene` (environment, keep_share) rendered at the resolution and samples of `sampling`
// (the same section for the search's metric; the `evaluate` section for the finer renders and fits).
std::shared_ptr<const BrdfScene> build_scene(const spec::Section& scene, const spec::Section& sampling);
spec::Schema scene_schema();
// `resolution` and `samples_per_pixel` with these defaults.
void add_sampling_keys(spec::Schema& s, std::int64_t resolution, std::int64_t samples_per_pixel);

}  // namespace pbrfit::jobs::brdf
