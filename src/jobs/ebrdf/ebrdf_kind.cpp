#include "pbrfit/jobs/ebrdf/ebrdf_kind.hpp"

#include <algorithm>

#include "pbrfit/ebrdf/footprint_samples.hpp"
#include "pbrfit/jobs/ebrdf/ebrdf_workload.hpp"
#include "pbrfit/jobs/ebrdf/normal_map_source.hpp"

namespace pbrfit::jobs::ebrdf {
namespace {

namespace eb = pbrfit::ebrdf;

eb::ViewGrid views_at(const spec::Section& s, const std::string& key) {
  const auto& v = s.get_int_list(key);
  return {std::size_t(v[0]), std::size_t(v[1])};
}

eb::EbrdfFitSettings fit_settings(const spec::Section& s) {
  eb::EbrdfFitSettings fit;
  const std::string& method = s.get_string("fit");
  fit.method = method == "sgd" ? eb::FitMethod::sgd
               : method == "nelder_mead" ? eb::FitMethod::nelder_mead
                                         : eb::FitMethod::descent;
  fit.descent.iterations = std::size_t(s.get_int("iterations"));
  fit.descent.axes = std::size_t(s.get_int("axes"));
  fit.search.axes = fit.descent.axes;
  fit.search.max_evaluations = std::size_t(s.get_int("max_evaluations"));
  fit.sgd.epochs = int(s.get_int("epochs"));
  fit.error_axes = std::size_t(s.get_int("error_axes"));
  return fit;
}

EbrdfSettings settings_from(const spec::JobSpec& job) {
  const spec::Section& s = job.kind_section;
  EbrdfSettings settings;
  auto loaded = load_normal_map(s, job.seed);
  settings.map = std::move(loaded.map);
  settings.map_source = std::move(loaded.description);
  settings.roughness = s.get_number("roughness");
  for (const std::string& name : {std::string("specular"), std::string("diffuse")}) {
    const auto& chosen = s.get_string_list("components");
    if (std::find(chosen.begin(), chosen.end(), name) == chosen.end()) continue;
    const bool specular = name == "specular";
    settings.components.push_back({specular ? eb::Component::specular : eb::Component::diffuse,
                                   views_at(s, specular ? "specular_views" : "diffuse_views")});
  }
  settings.samples = std::size_t(s.get_int("samples"));
  settings.tile = std::size_t(s.get_int("tile"));
  const std::size_t levels = eb::mip_levels(settings.map->size());
  settings.max_level = s.given("max_level") ? std::size_t(s.get_int("max_level")) : levels;
  if (settings.max_level > levels)
    s.reject("max_level", "exceeds the " + std::to_string(levels) + " levels above MIP 0 of a " +
                              std::to_string(settings.map->size()) + "-texel map");
  settings.fit = fit_settings(s);
  return settings;
}

std::unique_ptr<runtime::Workload> make_ebrdf(const spec::JobSpec& job) {
  return std::make_unique<EbrdfWorkload>(settings_from(job));
}

}  // namespace

JobKind ebrdf_kind() {
  return {"ebrdf", "LTC mip hierarchies prefiltering a normal map under area lights (Nahmias 2022)", ebrdf_schema(),
          make_ebrdf};
}

}  // namespace pbrfit::jobs::ebrdf
