#include "pbrfit/jobs/ebrdf/render_kind.hpp"

#include "pbrfit/jobs/ebrdf/render_workload.hpp"
#include "pbrfit/jobs/read_at_key.hpp"

namespace pbrfit::jobs::ebrdf {
namespace {

namespace eb = pbrfit::ebrdf;

spec::Schema render_schema() {
  spec::Schema s("ebrdf_render");
  s.string("tables", "the result file of a finished ebrdf job (both components)").require();
  s.string_list("scenes", 1, 2, "top: camera straight above; grazing: a low view facing the light", {"top", "grazing"})
      .defaults_to(std::vector<std::string>{"top", "grazing"});
  s.number_list("distances", 1, 32, "camera distances h, the map tiling once per world unit (top view at 128 "
                                     "pixels: about 0.54 h texels per pixel for a 128-texel map)")
      .defaults_to(std::vector<double>{1, 2, 4, 8, 16, 32});
  s.integer("resolution", "pixels per image side").range(8, 1024).defaults_to(std::int64_t{128});
  s.integer("min_samples", "ground truth: the fewest samples per pixel side").range(1, 48).defaults_to(std::int64_t{4});
  s.number("light_radiance", "radiance of the rectangular light").above(0.0).defaults_to(2.5);
  s.number("specular", "grey colour of the specular component").range(0.0, 1.0).defaults_to(0.3);
  s.number("diffuse", "grey colour of the diffuse component").range(0.0, 1.0).defaults_to(0.6);
  s.number("exposure", "factor on the linear radiance before the sRGB display transform").above(0.0).defaults_to(1.0);
  return s;
}

std::unique_ptr<runtime::Workload> make_render(const spec::JobSpec& job) {
  const spec::Section& s = job.kind_section;
  RenderSettings settings;
  settings.tables_path = s.get_string("tables");
  settings.tables = std::make_shared<const PrefilteredTables>(
      read_at_key(s, "tables", settings.tables_path, [&] { return load_prefiltered_tables(settings.tables_path); }));
  for (const auto& name : s.get_string_list("scenes"))
    settings.scenes.push_back(name == "top" ? eb::SceneView::top : eb::SceneView::grazing);
  settings.distances = s.get_number_list("distances");
  for (double d : settings.distances)
    if (!(d > 0.0)) s.reject("distances", "must all be positive");
  settings.resolution = std::size_t(s.get_int("resolution"));
  settings.shading = {s.get_number("light_radiance"), s.get_number("specular"), s.get_number("diffuse"),
                      std::size_t(s.get_int("min_samples"))};
  settings.exposure = s.get_number("exposure");
  return std::make_unique<RenderWorkload>(std::move(settings));
}

}  // namespace

JobKind ebrdf_render_kind() {
  return {"ebrdf_render", "reference renders of a prefiltered normal map: ground truth, naive and ours (Nahmias 2022)",
          render_schema(), make_render};
}

}  // namespace pbrfit::jobs::ebrdf
