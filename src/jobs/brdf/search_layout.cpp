// The result layout of a genBRDF search (brdf_search_workload.hpp; docs/results-brdf_search.md).
#include "pbrfit/jobs/brdf/brdf_inputs.hpp"
#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "result_tables.hpp"

namespace pbrfit::jobs::brdf {

using store::ValueType;

store::ResultLayout BrdfSearchWorkload::layout() const {
  store::Group g;
  g.name = "brdf";
  g.description = "genBRDF search: edits of the " + settings_.seed_name + " BRDF, Pareto front of the metric's error "
                  "vs the size of the syntax tree";
  std::vector<std::string> materials;
  for (std::size_t m = 0; m < settings_.data->materials(); ++m) materials.push_back(settings_.data->name(m));
  std::vector<std::string> inputs = pbrfit::brdf::direction_input_names();
  inputs.insert(inputs.end(), brdf_parameter_names().begin(), brdf_parameter_names().end());
  g.attributes = settings_.scene->attributes;
  g.attributes.insert({{"inputs", joined(inputs)},
                       {"parameters", "p0..p3, fitted per material and colour channel (they are inputs of an export)"},
                       {"training_materials", joined(materials)},
                       {"seed", settings_.seed_name},
                       {"material_class", settings_.material_class},
                       {"islands", std::to_string(settings_.islands)},
                       {"population", std::to_string(settings_.population)},
                       {"generations", std::to_string(settings_.generations)},
                       {"migration", std::to_string(settings_.migrants) + " every " +
                                         std::to_string(settings_.migration_interval) + " generations"},
                       {"error_measure", "L2 over materials and channels of sqrt(S'), the precomputed light metric"}});
  const std::vector<store::Field> front_fields = {
      {"expression", ValueType::text, "the BRDF (statements separated by '; '; inputs and p0..p3 as in `inputs`)"},
      {"constants", ValueType::text, "unused (the parameters are fitted per material)"},
      {"cost", ValueType::f64, "syntax tree size (nodes)"},
      {"operations", ValueType::u32, "operations of the tree"},
      {"piecewise", ValueType::u32, "min and max of the tree"},
      {"rmse", ValueType::f64, "the search's error on the training materials"},
      {"max_abs_error", ValueType::f64, "unused"},
      {"test_rmse", ValueType::f64, "unused"},
      {"generation", ValueType::u64, "when it was first evaluated"},
      {"knee", ValueType::u8, "1 for the knee of the front"}};
  g.tables = {
      records("front", "member", "the Pareto front of error vs tree size over every generation, by size", front_fields,
              {{"role", "front"}}),
      records("archive", "entry", "every tree that entered the front, in generation order",
              {{"expression", ValueType::text, "the BRDF"}, {"cost", ValueType::f64, "tree size"},
               {"error", ValueType::f64, "the search's error"}, {"generation", ValueType::u64, "generation"}}),
      records("log", "row", "a row per island and generation",
              {{"generation", ValueType::u64, "generation"}, {"island", ValueType::u32, "island"},
               {"best_error", ValueType::f64, "best error on the island"},
               {"median_size", ValueType::f64, "median tree size"},
               {"infeasible", ValueType::u32, "members whose error is not finite"},
               {"abandoned", ValueType::u32, "members whose fits stopped early, worse than the generation before's median"},
               {"migrants_in", ValueType::u32, "members replaced by migrants before breeding"}}),
      records("simplified", "row", "the knee of the front before and after culling sub-expressions that do not "
                                   "raise its error",
              {{"stage", ValueType::text, "knee or culled"}, {"expression", ValueType::text, "the BRDF"},
               {"cost", ValueType::f64, "tree size"}, {"error", ValueType::f64, "the search's error, refitted"}}),
  };
  if (!settings_.evaluation.enabled) return {{g}};
  return {{g, evaluation_group()}};
}

}  // namespace pbrfit::jobs::brdf
