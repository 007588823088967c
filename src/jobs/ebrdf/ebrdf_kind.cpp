// The `ebrdf` kind: the keys of its section (docs/job-files.md, kind `ebrdf`), each bound to the settings it
// fills, and the workload they make.
#include "pbrfit/jobs/ebrdf/ebrdf_kind.hpp"

#include <algorithm>
#include <optional>

#include "pbrfit/ebrdf/footprint_samples.hpp"
#include "pbrfit/jobs/ebrdf/ebrdf_workload.hpp"
#include "pbrfit/jobs/ebrdf/normal_map_source.hpp"
#include "pbrfit/jobs/read_named_file.hpp"
#include "pbrfit/spec/keys.hpp"

namespace pbrfit::jobs::ebrdf {
namespace {

namespace eb = pbrfit::ebrdf;

// What the section holds, beside the settings it fills.
struct EbrdfSection {
  std::uint64_t seed = 0;  // the job's: it seeds a built-in map
  std::string normal_map;
  spec::Written<std::size_t> size;
  std::vector<std::string> components;
  eb::ViewGrid specular_views, diffuse_views;
  std::optional<std::size_t> max_level;
  EbrdfSettings settings;
};

eb::ViewGrid view_grid(const std::vector<std::int64_t>& v) { return {std::size_t(v[0]), std::size_t(v[1])}; }

spec::Keys<EbrdfSection> ebrdf_keys() {
  using S = EbrdfSection;
  spec::Keys<S> k("ebrdf");
  k.string("normal_map",
           "stone, glitter or scratches (built in), or the path of a PNG or TGA tangent-space normal map, square, "
           "with a power-of-two side of at most 512",
           &S::normal_map)
      .require();
  k.integer("size", "side of a built-in normal map, a power of two", &S::size).range(2, 512).defaults_to(std::int64_t{128});
  k.number("roughness", "perceptual roughness of the specular base BRDF (GGX alpha = roughness^2)",
           [](S& s, double r) { s.settings.roughness = r; })
      .range(0.01, 1.0)
      .defaults_to(0.1);
  k.string_list("components", 1, 2, "which effective BRDFs to prefilter", &S::components, {"specular", "diffuse"})
      .defaults_to(std::vector<std::string>{"specular", "diffuse"});
  k.integer_list("specular_views", 2, 2, "tabulated views of the specular tables: [elevations, azimuths]",
                 [](S& s, const std::vector<std::int64_t>& v) { s.specular_views = view_grid(v); })
      .range(1, 64)
      .defaults_to(std::vector<std::int64_t>{8, 16});
  k.integer_list("diffuse_views", 2, 2, "tabulated views of the diffuse tables: [elevations, azimuths]",
                 [](S& s, const std::vector<std::int64_t>& v) { s.diffuse_views = view_grid(v); })
      .range(1, 64)
      .defaults_to(std::vector<std::int64_t>{2, 4});
  k.integer("samples", "directions per effective BRDF", [](S& s, std::int64_t n) { s.settings.samples = std::size_t(n); })
      .range(8, 4096)
      .defaults_to(std::int64_t{128});
  k.integer("max_level", "highest mip level to fit (default: every level, up to the 1 x 1 mip)", &S::max_level)
      .range(1, 9);
  k.integer("tile", "mip texels per side of a work item's tile (and of the tables' chunks)",
            [](S& s, std::int64_t n) { s.settings.tile = std::size_t(n); })
      .range(1, 512)
      .defaults_to(std::int64_t{8});
  k.choice<eb::FitMethod>("fit",
                          {{"descent", eb::FitMethod::descent},
                           {"nelder_mead", eb::FitMethod::nelder_mead},
                           {"sgd", eb::FitMethod::sgd}},
                          "descent: gradient descent on the sliced Wasserstein distance from moment matching; "
                          "nelder_mead: the fitting engine's Nelder-Mead from the same start; sgd: the thesis' "
                          "baseline, SGD from the identity",
                          [](S& s, eb::FitMethod m) { s.settings.fit.method = m; })
      .defaults_to(std::string("descent"));
  k.integer("iterations", "descent: gradient steps per fit",
            [](S& s, std::int64_t n) { s.settings.fit.descent.iterations = std::size_t(n); })
      .range(0, 100'000)
      .defaults_to(std::int64_t{30});
  k.integer("axes", "descent, nelder_mead: projection axes of the search's sliced Wasserstein distance",
            [](S& s, std::int64_t n) { s.settings.fit.descent.axes = s.settings.fit.search.axes = std::size_t(n); })
      .range(1, 1024)
      .defaults_to(std::int64_t{12});
  k.integer("max_evaluations", "nelder_mead: distance evaluations per fit",
            [](S& s, std::int64_t n) { s.settings.fit.search.max_evaluations = std::size_t(n); })
      .range(10, 10'000'000)
      .defaults_to(std::int64_t{400});
  k.integer("epochs", "sgd: epochs per fit", [](S& s, std::int64_t n) { s.settings.fit.sgd.epochs = int(n); })
      .range(1, 100'000)
      .defaults_to(std::int64_t{100});
  k.integer("error_axes", "projection axes of the reported fit error",
            [](S& s, std::int64_t n) { s.settings.fit.error_axes = std::size_t(n); })
      .range(1, 1024)
      .defaults_to(std::int64_t{32});

  k.check("size", [](S& s) -> std::string {
    if (!is_builtin_normal_map(s.normal_map)) return s.size.written ? "applies to the built-in normal maps only" : "";
    return eb::is_power_of_two(s.size.value) ? "" : "must be a power of two";
  });
  k.check("normal_map", [](S& s) {
    LoadedNormalMap loaded;
    std::string problem;
    if (is_builtin_normal_map(s.normal_map)) loaded = builtin_normal_map(s.normal_map, s.size.value, s.seed);
    else problem = read_named_file(s.normal_map, [&] { loaded = normal_map_file(s.normal_map); });
    s.settings.map = std::move(loaded.map);
    s.settings.map_source = std::move(loaded.description);
    return problem;
  });
  k.check("components", [](S& s) {
    for (const auto component : {eb::Component::specular, eb::Component::diffuse}) {  // table order
      const std::string name = component_name(component);
      if (std::find(s.components.begin(), s.components.end(), name) == s.components.end()) continue;
      s.settings.components.push_back({component, component == eb::Component::specular ? s.specular_views : s.diffuse_views});
    }
    return std::string();
  });
  k.check("max_level", [](S& s) -> std::string {
    const std::size_t levels = eb::mip_levels(s.settings.map->size());
    s.settings.max_level = s.max_level.value_or(levels);
    if (s.settings.max_level <= levels) return "";
    return "exceeds the " + std::to_string(levels) + " levels above MIP 0 of a " +
           std::to_string(s.settings.map->size()) + "-texel map";
  });
  return k;
}

const spec::Keys<EbrdfSection>& ebrdf_section_keys() {
  static const spec::Keys<EbrdfSection> keys = ebrdf_keys();
  return keys;
}

std::unique_ptr<runtime::Workload> make_ebrdf(const spec::JobSpec& job) {
  EbrdfSection start;
  start.seed = job.seed;
  return std::make_unique<EbrdfWorkload>(ebrdf_section_keys().read(job.kind_section, std::move(start)).settings);
}

}  // namespace

JobKind ebrdf_kind() {
  return {"ebrdf", "LTC mip hierarchies prefiltering a normal map under area lights (Nahmias 2022)",
          ebrdf_section_keys().schema(), make_ebrdf};
}

}  // namespace pbrfit::jobs::ebrdf
