#pragma once
// The settings of an `ebrdf` job (docs/job-files.md), as the workload uses them.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "pbrfit/ebrdf/base_lobe.hpp"
#include "pbrfit/ebrdf/ebrdf_fit.hpp"
#include "pbrfit/ebrdf/normal_map.hpp"
#include "pbrfit/ebrdf/view_grid.hpp"

namespace pbrfit::jobs::ebrdf {

struct ComponentSettings {
  pbrfit::ebrdf::Component component = pbrfit::ebrdf::Component::specular;
  pbrfit::ebrdf::ViewGrid views;
};

struct EbrdfSettings {
  std::shared_ptr<const pbrfit::ebrdf::NormalMap> map;  // loaded once per process, shared by its threads
  std::string map_source;                               // "stone (procedural, 128 x 128)" or the file's path
  double roughness = 0.1;                               // perceptual; GGX alpha = roughness^2
  std::vector<ComponentSettings> components;            // in table order: specular first
  std::size_t samples = 128;                            // directions per eBRDF
  std::size_t tile = 8;                                 // mip texels per work item side
  std::size_t max_level = 0;                            // highest mip level fitted (1 .. log2(size))
  pbrfit::ebrdf::EbrdfFitSettings fit;
};

const char* component_name(pbrfit::ebrdf::Component c);
const char* fit_method_name(pbrfit::ebrdf::FitMethod m);

}  // namespace pbrfit::jobs::ebrdf
