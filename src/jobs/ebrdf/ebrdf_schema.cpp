// The schema of an `ebrdf` job's section (docs/job-files.md, kind `ebrdf`).
#include "pbrfit/jobs/ebrdf/ebrdf_kind.hpp"

namespace pbrfit::jobs::ebrdf {

spec::Schema ebrdf_schema() {
  spec::Schema s("ebrdf");
  s.string("normal_map", "stone, glitter or scratches (built in), or the path of a PNG or TGA tangent-space normal "
                         "map, square, with a power-of-two side of at most 512")
      .require();
  s.integer("size", "side of a built-in normal map, a power of two").range(2, 512).defaults_to(std::int64_t{128});
  s.number("roughness", "perceptual roughness of the specular base BRDF (GGX alpha = roughness^2)")
      .range(0.01, 1.0)
      .defaults_to(0.1);
  s.string_list("components", 1, 2, "which effective BRDFs to prefilter", {"specular", "diffuse"})
      .defaults_to(std::vector<std::string>{"specular", "diffuse"});
  s.integer_list("specular_views", 2, 2, "tabulated views of the specular tables: [elevations, azimuths]")
      .range(1, 64)
      .defaults_to(std::vector<std::int64_t>{8, 16});
  s.integer_list("diffuse_views", 2, 2, "tabulated views of the diffuse tables: [elevations, azimuths]")
      .range(1, 64)
      .defaults_to(std::vector<std::int64_t>{2, 4});
  s.integer("samples", "directions per effective BRDF").range(8, 4096).defaults_to(std::int64_t{128});
  s.integer("max_level", "highest mip level to fit (default: every level, up to the 1 x 1 mip)").range(1, 9);
  s.integer("tile", "mip texels per side of a work item's tile (and of the tables' chunks)")
      .range(1, 512)
      .defaults_to(std::int64_t{8});
  s.choice("fit", {"descent", "nelder_mead", "sgd"},
           "descent: gradient descent on the sliced Wasserstein distance from moment matching; nelder_mead: the "
           "fitting engine's Nelder-Mead from the same start; sgd: the thesis' baseline, SGD from the identity")
      .defaults_to(std::string("descent"));
  s.integer("iterations", "descent: gradient steps per fit").range(0, 100'000).defaults_to(std::int64_t{30});
  s.integer("axes", "descent, nelder_mead: projection axes of the search's sliced Wasserstein distance")
      .range(1, 1024)
      .defaults_to(std::int64_t{12});
  s.integer("max_evaluations", "nelder_mead: distance evaluations per fit").range(10, 10'000'000).defaults_to(std::int64_t{400});
  s.integer("epochs", "sgd: epochs per fit").range(1, 100'000).defaults_to(std::int64_t{100});
  s.integer("error_axes", "projection axes of the reported fit error").range(1, 1024).defaults_to(std::int64_t{32});
  return s;
}

}  // namespace pbrfit::jobs::ebrdf
