#pragma once
// A validated `brdf_search` job: the training materials' metric data, the scene, the seed BRDF and the edit
// grammar (operators, scalars, codebank), the island model, the fitting effort and the evaluation.
//
// Invariants (brdf_search_kind.cpp establishes them): islands >= 1; population even and >= 2; generations
// >= 1; migration_interval >= 1; migrants < population; chunk >= 1; the seed compiles; data and scene are
// set and shared read-only by every thread.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "pbrfit/gp/edit_evolution.hpp"
#include "pbrfit/gp/parameter_fit.hpp"
#include "pbrfit/jobs/brdf/brdf_scene.hpp"
#include "pbrfit/jobs/brdf/material_source.hpp"
#include "pbrfit/jobs/brdf/metric_data.hpp"

namespace pbrfit::jobs::brdf {

// Which front members the evaluation fits and renders beside the seed.
enum class EvaluatedMember : std::uint8_t {
  comparable,  // the most accurate member at most comparable_size x the seed's size
  knee,        // the knee after culling (brdf/simplified)
  best,        // the most accurate member
};

// A named BRDF (seed_brdfs.hpp) evaluated beside the seed but never searched: the paper's own, say.
struct ReferenceBrdf {
  std::string name;
  gp::SyntaxTree tree;
};

struct EvaluationSettings {
  bool enabled = true;
  std::vector<std::string> training, testing;  // material names, each set in the job's order
  MaterialSource source;
  std::vector<ReferenceBrdf> references;  // none named the seed, none twice
  std::vector<EvaluatedMember> members = {EvaluatedMember::comparable, EvaluatedMember::knee};
  double comparable_size = 1.5;
  gp::ParameterFitOptions fit{16, 1000};
  double exposure = 1.0;  // of the PNG renders and the image errors
  std::shared_ptr<const BrdfScene> scene;  // of the renders, finer than the search's; set when enabled
};

struct BrdfSearchSettings {
  std::shared_ptr<const BrdfScene> scene;
  std::shared_ptr<const MetricData> data;  // the training materials
  std::string seed_name;
  gp::SyntaxTree seed{{gp::SyntaxNode{}}};
  gp::EditGrammar grammar;
  std::size_t islands = 4;
  std::size_t population = 256;  // per island
  std::size_t generations = 100;
  std::size_t migration_interval = 5;
  std::size_t migrants = 1;
  std::size_t chunk = 4;  // trees per evaluation work item
  bool abandon_poor = true;  // stop fitting a candidate once it is worse than the last generation's median
  gp::EditEvolutionOptions evolution;
  gp::ParameterFitOptions fit;
  EvaluationSettings evaluation;
  std::string material_class;  // metals, dielectrics or custom
};

const char* member_name(EvaluatedMember member);

}  // namespace pbrfit::jobs::brdf
