#pragma once
// A `brdf_search` section as written, before the materials are loaded and the scenes built (the keys:
// brdf_search_schema.cpp; the settings: brdf_search_kind.cpp). Private to the brdf jobs.
#include <string>
#include <vector>

#include "pbrfit/gp/parameter_fit.hpp"
#include "pbrfit/jobs/brdf/brdf_scene.hpp"
#include "pbrfit/jobs/brdf/brdf_search_settings.hpp"
#include "pbrfit/spec/keys.hpp"

namespace pbrfit::jobs::brdf {

struct EvaluateSection {
  bool enabled = true;
  spec::Located<std::vector<std::string>> references;
  std::vector<EvaluatedMember> members;
  double comparable_size = 1.5;
  gp::ParameterFitOptions fit;
  std::size_t resolution = 128, samples_per_pixel = 64;  // of the renders
  double exposure = 1.0;
};

struct BrdfSearchSection {
  std::string materials;  // metals, dielectrics or custom
  spec::Located<std::vector<std::string>> training, testing;
  std::string merl_directory, cache;
  SceneSection scene;
  std::string seed_brdf;
  std::vector<std::string> codebank, unary, binary;
  std::vector<double> constants;
  std::size_t islands = 0, population = 0, generations = 0, migration_interval = 0, migrants = 0;
  std::size_t tournament_size = 0, max_genome = 0, max_nodes = 0, chunk = 0;
  bool abandon_poor = true;
  gp::ParameterFitOptions fit;
  EvaluateSection evaluate;
};

spec::Keys<BrdfSearchSection> brdf_search_keys();

}  // namespace pbrfit::jobs::brdf
