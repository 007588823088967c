#include "pbrfit/jobs/brdf/brdf_search_kind.hpp"

#include <unistd.h>

#include <stdexcept>

#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/jobs/brdf/brdf_inputs.hpp"
#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "pbrfit/jobs/brdf/material_sets.hpp"
#include "pbrfit/jobs/brdf/seed_brdfs.hpp"

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

gp::EditGrammar grammar_of(const spec::Section& s, const gp::SyntaxTree& seed) {
  gp::EditGrammar g;
  g.unary = operators(s.get_string_list("unary"));
  g.binary = operators(s.get_string_list("binary"));
  g.inputs = brdf_input_count;
  g.parameters = brdf_parameter_count;
  g.constants = s.get_number_list("constants");
  std::vector<gp::SyntaxTree> seeds = {seed};
  for (const auto& name : s.get_string_list("codebank")) seeds.push_back(seed_tree(name));
  g.codebank = gp::codebank_of(seeds);
  g.max_nodes = std::size_t(s.get_int("max_nodes"));
  if (g.max_nodes < seed.size()) s.reject("max_nodes", "is smaller than the seed BRDF (" + std::to_string(seed.size()) + " nodes)");
  return g;
}

gp::ParameterFitOptions fit_of(const spec::Section& s) {
  gp::ParameterFitOptions f{std::size_t(s.get_int("starts")), std::size_t(s.get_int("evaluations_per_start")),
                            s.get_number("lower"), s.get_number("upper"), s.get_number("start_lower"),
                            s.get_number("start_upper"), s.get_bool("warm_start")};
  if (f.lower >= f.upper) s.reject("upper", "must be above 'lower'");
  if (f.start_lower > f.start_upper) s.reject("start_upper", "must be at least 'start_lower'");
  if (f.start_lower < f.lower || f.start_upper > f.upper) s.reject("start_lower", "starts must lie within [lower, upper]");
  return f;
}

// The class's lists unless the job gives its own (which `custom` requires).
std::vector<std::string> materials_of(const spec::Section& s, const std::string& key) {
  const auto set = material_set(s.get_string("materials"));
  if (s.given(key)) return s.get_string_list(key);
  if (!set) s.reject(key, "is needed when 'materials' is custom");
  return key == "training" ? set->training : set->testing;
}

void check_readable(const spec::Section& s, const std::string& key, const std::vector<std::string>& names,
                    const MaterialSource& source) {
  for (const auto& name : names)
    if (const auto path = material_path(name, source); access(path.c_str(), R_OK) != 0)
      s.reject(key, "names " + name + ", but " + path + " cannot be read");
}

std::vector<ReferenceBrdf> references_of(const spec::Section& s) {
  const auto& e = s.get_section("evaluate");
  std::vector<ReferenceBrdf> out;
  for (const auto& name : e.get_string_list("references")) {
    if (name == s.get_string("seed_brdf"))
      e.reject("references", "names the seed, " + name + ", which is always evaluated");
    for (const auto& r : out)
      if (r.name == name) e.reject("references", "names " + name + " twice");
    out.push_back({name, seed_tree(name)});
  }
  return out;
}

EvaluationSettings evaluation_of(const spec::Section& s, const MaterialSource& source) {
  const auto& e = s.get_section("evaluate");
  EvaluationSettings out;
  out.references = references_of(s);
  out.enabled = e.get_bool("enabled");
  out.training = materials_of(s, "training");
  out.testing = materials_of(s, "testing");
  out.source = source;
  out.members.clear();
  for (const auto& m : e.get_string_list("members"))
    out.members.push_back(m == "knee" ? EvaluatedMember::knee : m == "best" ? EvaluatedMember::best : EvaluatedMember::comparable);
  out.comparable_size = e.get_number("comparable_size");
  out.fit = fit_of(e.get_section("fit"));
  out.exposure = e.get_number("exposure");
  check_readable(s, "testing", out.testing, source);
  return out;
}

std::shared_ptr<const MetricData> training_data(const spec::Section& s, const BrdfScene& scene,
                                                const std::vector<std::string>& names, const MaterialSource& source) {
  check_readable(s, "training", names, source);
  std::vector<pbrfit::brdf::MerlTable> tables;
  for (const auto& name : names) tables.push_back(load_material(name, source));
  try {
    return std::make_shared<const MetricData>(scene.table, tables, names);
  } catch (const std::invalid_argument& e) {
    s.reject("training", e.what());
  }
}

void check_island_model(const spec::Section& s, const BrdfSearchSettings& b) {
  if (b.population % 2 != 0) s.reject("population", "must be even (parents and offspring are paired)");
  if (b.migrants >= b.population) s.reject("migrants", "must be smaller than 'population'");
  if (b.evolution.tournament_size > b.population) s.reject("tournament_size", "must be at most 'population'");
}

std::unique_ptr<runtime::Workload> make_brdf_search(const spec::JobSpec& job) {
  return std::make_unique<BrdfSearchWorkload>(brdf_search_settings(job.kind_section));
}

}  // namespace

BrdfSearchSettings brdf_search_settings(const spec::Section& s) {
  BrdfSearchSettings b;
  b.material_class = s.get_string("materials");
  b.seed_name = s.get_string("seed_brdf");
  b.seed = seed_tree(b.seed_name);
  b.grammar = grammar_of(s, b.seed);
  b.islands = std::size_t(s.get_int("islands"));
  b.population = std::size_t(s.get_int("population"));
  b.generations = std::size_t(s.get_int("generations"));
  b.migration_interval = std::size_t(s.get_int("migration_interval"));
  b.migrants = std::size_t(s.get_int("migrants"));
  b.chunk = std::size_t(s.get_int("chunk"));
  b.abandon_poor = s.get_bool("abandon_poor");
  b.evolution = {std::size_t(s.get_int("tournament_size")), std::size_t(s.get_int("max_genome"))};
  check_island_model(s, b);
  b.fit = fit_of(s.get_section("fit"));
  const MaterialSource source{s.get_string("merl_directory"), "", s.get_string("cache")};
  b.evaluation = evaluation_of(s, source);
  b.scene = build_scene(s.get_section("scene"), s.get_section("scene"));
  if (b.evaluation.enabled) b.evaluation.scene = build_scene(s.get_section("scene"), s.get_section("evaluate"));
  b.data = training_data(s, *b.scene, b.evaluation.training, source);
  return b;
}

JobKind brdf_search_kind() {
  return {"brdf_search", "genBRDF: island GP over edits of a seed BRDF against measured materials, then renders",
          brdf_search_schema(), make_brdf_search};
}

}  // namespace pbrfit::jobs::brdf
