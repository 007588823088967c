#include "pbrfit/jobs/ebrdf/render_kind.hpp"

#include "pbrfit/jobs/ebrdf/render_workload.hpp"
#include "pbrfit/jobs/read_named_file.hpp"
#include "pbrfit/spec/keys.hpp"

namespace pbrfit::jobs::ebrdf {
namespace {

namespace eb = pbrfit::ebrdf;

spec::Keys<RenderSettings> render_keys() {
  using S = RenderSettings;
  spec::Keys<S> k("ebrdf_render");
  k.string("tables", "the result file of a finished ebrdf job (both components)", &S::tables_path).require();
  k.string_list("scenes", 1, 2, "top: camera straight above; grazing: a low view facing the light",
                [](S& s, const std::vector<std::string>& names) {
                  for (const auto& name : names) s.scenes.push_back(name == "top" ? eb::SceneView::top : eb::SceneView::grazing);
                },
                {"top", "grazing"})
      .defaults_to(std::vector<std::string>{"top", "grazing"});
  k.number_list("distances", 1, 32,
                "camera distances h, the map tiling once per world unit (top view at 128 pixels: about 0.54 h "
                "texels per pixel for a 128-texel map)",
                &S::distances)
      .defaults_to(std::vector<double>{1, 2, 4, 8, 16, 32});
  k.integer("resolution", "pixels per image side", &S::resolution).range(8, 1024).defaults_to(std::int64_t{128});
  k.integer("min_samples", "ground truth: the fewest samples per pixel side",
            [](S& s, std::int64_t n) { s.shading.min_samples = std::size_t(n); })
      .range(1, 48)
      .defaults_to(std::int64_t{4});
  k.number("light_radiance", "radiance of the rectangular light", [](S& s, double v) { s.shading.light_radiance = v; })
      .above(0.0)
      .defaults_to(2.5);
  k.number("specular", "grey colour of the specular component", [](S& s, double v) { s.shading.specular = v; })
      .range(0.0, 1.0)
      .defaults_to(0.3);
  k.number("diffuse", "grey colour of the diffuse component", [](S& s, double v) { s.shading.diffuse = v; })
      .range(0.0, 1.0)
      .defaults_to(0.6);
  k.choice<eb::TableFiltering>(
       "filtering", {{"results", eb::TableFiltering::results}, {"matrices", eb::TableFiltering::matrices}},
       "ours: results blends what each of the up to 8 mip texels of a lookup shades; matrices blends their "
       "matrices and shades once, as a cheap shader would",
       [](S& s, eb::TableFiltering f) { s.shading.filtering = f; })
      .defaults_to(std::string("results"));
  k.number("exposure", "factor on the linear radiance before the sRGB display transform", &S::exposure)
      .above(0.0)
      .defaults_to(1.0);
  k.check("tables", [](S& s) {
    return read_named_file(s.tables_path, [&] {
      s.tables = std::make_shared<const PrefilteredTables>(load_prefiltered_tables(s.tables_path));
    });
  });
  k.check("distances", [](S& s) -> std::string {
    for (double d : s.distances)
      if (!(d > 0.0)) return "must all be positive";
    return "";
  });
  return k;
}

const spec::Keys<RenderSettings>& render_section_keys() {
  static const spec::Keys<RenderSettings> keys = render_keys();
  return keys;
}

std::unique_ptr<runtime::Workload> make_render(const spec::JobSpec& job) {
  return std::make_unique<RenderWorkload>(render_section_keys().read(job.kind_section));
}

}  // namespace

JobKind ebrdf_render_kind() {
  return {"ebrdf_render", "reference renders of a prefiltered normal map: ground truth, naive and ours (Nahmias 2022)",
          render_section_keys().schema(), make_render};
}

}  // namespace pbrfit::jobs::ebrdf
