#include "pbrfit/jobs/brdf/brdf_search_kind.hpp"

#include <unistd.h>

#include <optional>
#include <stdexcept>

#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/jobs/brdf/brdf_inputs.hpp"
#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "pbrfit/jobs/brdf/material_sets.hpp"
#include "pbrfit/jobs/brdf/seed_brdfs.hpp"
#include "brdf_search_section.hpp"

namespace pbrfit::jobs::brdf {
namespace {

gp::SyntaxTree seed_tree(const std::string& name) {
  const auto parsed = gp::parse_expression(find_seed(name)->expression, {pbrfit::brdf::direction_input_names(), brdf_parameter_names()});
  if (const auto* error = std::get_if<gp::ExpressionError>(&parsed))
    throw std::logic_error("seed BRDF " + name + " does not parse: " + error->message);
  const auto& p = std::get<gp::ParsedExpression>(parsed);
  return gp::tree_of(p.program, p.parameter_slots);
}

gp::OperatorSet operators(const std::vector<std::string>& names) {
  gp::OperatorSet set;
  for (const auto& n : names) set.insert(*gp::opcode_named(n));
  return set;
}

gp::EditGrammar grammar_of(const BrdfSearchSection& s, const gp::SyntaxTree& seed) {
  gp::EditGrammar g;
  g.unary = operators(s.unary);
  g.binary = operators(s.binary);
  g.inputs = brdf_input_count;
  g.parameters = brdf_parameter_count;
  g.constants = s.constants;
  std::vector<gp::SyntaxTree> seeds = {seed};
  for (const auto& name : s.codebank) seeds.push_back(seed_tree(name));
  g.codebank = gp::codebank_of(seeds);
  g.max_nodes = s.max_nodes;
  return g;
}

// The job's list, else the class's (`custom` has none, so it needs the job's).
std::vector<std::string> materials_of(const spec::Located<std::vector<std::string>>& list,
                                      const std::optional<MaterialSet>& set, std::vector<std::string> MaterialSet::*of) {
  if (list.written) return list.value;
  if (!set) list.reject("is needed when 'materials' is custom");
  return (*set).*of;
}

void check_readable(const spec::Located<std::vector<std::string>>& list, const std::vector<std::string>& names,
                    const MaterialSource& source) {
  for (const auto& name : names)
    if (const auto path = material_path(name, source); access(path.c_str(), R_OK) != 0)
      list.reject("names " + name + ", but " + path + " cannot be read");
}

std::vector<ReferenceBrdf> references_of(const BrdfSearchSection& s) {
  const auto& references = s.evaluate.references;
  std::vector<ReferenceBrdf> out;
  for (const auto& name : references.value) {
    if (name == s.seed_brdf) references.reject("names the seed, " + name + ", which is always evaluated");
    for (const auto& r : out)
      if (r.name == name) references.reject("names " + name + " twice");
    out.push_back({name, seed_tree(name)});
  }
  return out;
}

EvaluationSettings evaluation_of(const BrdfSearchSection& s, const MaterialSource& source) {
  const EvaluateSection& e = s.evaluate;
  EvaluationSettings out;
  out.references = references_of(s);
  out.enabled = e.enabled;
  const auto set = material_set(s.materials);
  out.training = materials_of(s.training, set, &MaterialSet::training);
  out.testing = materials_of(s.testing, set, &MaterialSet::testing);
  out.source = source;
  out.members = e.members;
  out.comparable_size = e.comparable_size;
  out.fit = e.fit;
  out.exposure = e.exposure;
  check_readable(s.testing, out.testing, source);
  return out;
}

std::shared_ptr<const MetricData> training_data(const BrdfSearchSection& s, const BrdfScene& scene,
                                                const std::vector<std::string>& names, const MaterialSource& source) {
  check_readable(s.training, names, source);
  std::vector<pbrfit::brdf::MerlTable> tables;
  for (const auto& name : names) tables.push_back(load_material(name, source));
  try {
    return std::make_shared<const MetricData>(scene.table, tables, names);
  } catch (const std::invalid_argument& e) {
    s.training.reject(e.what());
  }
}

// The settings of a section as written and checked: the materials loaded and the scenes built.
BrdfSearchSettings settings_of(const BrdfSearchSection& s) {
  BrdfSearchSettings b;
  b.material_class = s.materials;
  b.seed_name = s.seed_brdf;
  b.seed = seed_tree(b.seed_name);
  b.grammar = grammar_of(s, b.seed);
  b.islands = s.islands;
  b.population = s.population;
  b.generations = s.generations;
  b.migration_interval = s.migration_interval;
  b.migrants = s.migrants;
  b.chunk = s.chunk;
  b.abandon_poor = s.abandon_poor;
  b.evolution = {s.tournament_size, s.max_genome};
  b.fit = s.fit;
  const MaterialSource source{s.merl_directory, "", s.cache};
  b.evaluation = evaluation_of(s, source);
  b.scene = build_scene(s.scene, s.scene.resolution, s.scene.samples_per_pixel);
  if (b.evaluation.enabled)
    b.evaluation.scene = build_scene(s.scene, s.evaluate.resolution, s.evaluate.samples_per_pixel);
  b.data = training_data(s, *b.scene, b.evaluation.training, source);
  return b;
}

// The keys with the checks that span them, in the order a job is refused by them.
spec::Keys<BrdfSearchSection> checked_keys() {
  using S = BrdfSearchSection;
  auto k = brdf_search_keys();
  k.check("max_nodes", [](S& s) -> std::string {
    const std::size_t seed = seed_tree(s.seed_brdf).size();
    return s.max_nodes < seed ? "is smaller than the seed BRDF (" + std::to_string(seed) + " nodes)" : "";
  });
  k.check("population", [](S& s) -> std::string {
    return s.population % 2 != 0 ? "must be even (parents and offspring are paired)" : "";
  });
  k.check("migrants", [](S& s) -> std::string {
    return s.migrants >= s.population ? "must be smaller than 'population'" : "";
  });
  k.check("tournament_size", [](S& s) -> std::string {
    return s.tournament_size > s.population ? "must be at most 'population'" : "";
  });
  return k;
}

const spec::Keys<BrdfSearchSection>& keys() {
  static const spec::Keys<BrdfSearchSection> keys = checked_keys();
  return keys;
}

std::unique_ptr<runtime::Workload> make_brdf_search(const spec::JobSpec& job) {
  return std::make_unique<BrdfSearchWorkload>(brdf_search_settings(job.kind_section));
}

}  // namespace

const spec::Schema& brdf_search_schema() { return keys().schema(); }

BrdfSearchSettings brdf_search_settings(const spec::Section& section) {
  return settings_of(keys().read(section));
}

JobKind brdf_search_kind() {
  return {"brdf_search", "genBRDF: island GP over edits of a seed BRDF against measured materials, then renders",
          brdf_search_schema(), make_brdf_search};
}

}  // namespace pbrfit::jobs::brdf
