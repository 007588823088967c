#include "pbrfit/jobs/symreg/symreg_kind.hpp"

#include <stdexcept>

#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/jobs/symreg/symreg_workload.hpp"

namespace pbrfit::jobs::symreg {
namespace {

gp::Opcode opcode_of(const std::string& name) {
  const auto op = gp::opcode_named(name);
  if (!op) throw std::logic_error("symreg: the schema let an unknown operator through: " + name);
  return *op;
}

gp::ProgramShape shape_of(const spec::Section& s) {
  gp::ProgramShape shape;
  shape.operators = {};
  for (const auto& name : s.get_string_list("operators")) shape.operators.insert(opcode_of(name));
  shape.max_length = std::size_t(s.get_int("max_length"));
  shape.initial_max_length = std::min<std::size_t>(shape.initial_max_length, shape.max_length);
  shape.constant_probability = s.get_number("constant_probability");
  shape.constant_min = s.get_number("constant_min");
  shape.constant_max = s.get_number("constant_max");
  if (shape.constant_min > shape.constant_max) s.reject("constant_max", "must be at least 'constant_min'");
  return shape;
}

gp::FitnessOptions fitness_of(const spec::Section& s) {
  gp::FitnessOptions f;
  f.precision = s.get_string("precision") == "float64" ? gp::Precision::float64 : gp::Precision::float32;
  f.error.measure = *gp::error_measure_named(s.get_string("error"));
  f.costs.piecewise_penalty = s.get_number("piecewise_penalty");
  for (const auto& item : s.get_section_list("costs")) f.costs[opcode_of(item.get_string("operator"))] = item.get_number("cost");
  return f;
}

gp::EvolveOptions evolve_of(const spec::Section& s) {
  gp::EvolveOptions o;
  o.shape = shape_of(s);
  o.fitness = fitness_of(s);
  o.population_size = std::size_t(s.get_int("population"));
  o.selection = s.get_string("selection") == "tournament" ? gp::SelectionScheme::tournament : gp::SelectionScheme::pareto;
  o.piecewise_objective = s.get_bool("piecewise_objective");
  o.tournament_size = std::size_t(s.get_int("tournament_size"));
  o.elites = std::size_t(s.get_int("elites"));
  if (o.elites >= o.population_size) s.reject("elites", "must be smaller than 'population'");
  o.crossover_rate = s.get_number("crossover_rate");
  o.mutation_rate = s.get_number("mutation_rate");
  o.constant_fits_per_generation = std::size_t(s.get_int("constant_fits_per_generation"));
  o.constants.max_evaluations = std::size_t(s.get_int("constant_fit_evaluations"));
  o.restart_after_stall = std::size_t(s.get_int("restart_after_stall"));
  o.target_error = s.get_number("target_error");
  return o;
}

std::vector<Anchor> anchors_of(const spec::Section& s, const SymregData& data) {
  std::vector<Anchor> anchors;
  for (const auto& item : s.get_section_list("anchors")) {
    std::size_t output = 0;
    if (item.given("output")) {
      while (output < data.outputs.size() && data.outputs[output].name != item.get_string("output")) ++output;
      if (output == data.outputs.size()) item.reject("output", "is '" + item.get_string("output") + "', not an output of the data");
    } else if (data.outputs.size() > 1) {
      item.reject("name", "needs 'output' when the data has several outputs");
    }
    const auto parsed = gp::parse_expression(item.get_string("expression"), {data.outputs[output].inputs, {}});
    if (const auto* error = std::get_if<gp::ExpressionError>(&parsed))
      item.reject("expression", "has an error at line " + std::to_string(error->line) + ", column " +
                                    std::to_string(error->column) + ": " + error->message);
    anchors.push_back({item.get_string("name"), output, item.get_string("expression"),
                       std::get<gp::ParsedExpression>(parsed).program});
  }
  return anchors;
}

std::unique_ptr<runtime::Workload> make_symreg(const spec::JobSpec& job) {
  return std::make_unique<SymregWorkload>(symreg_settings(job.kind_section));
}

}  // namespace

SymregSettings symreg_settings(const spec::Section& s) {
  SymregSettings settings;
  settings.evolve = evolve_of(s);
  settings.islands = std::size_t(s.get_int("islands"));
  settings.generations = std::size_t(s.get_int("generations"));
  settings.migration_interval = std::size_t(s.get_int("migration_interval"));
  settings.migrants = std::size_t(s.get_int("migrants"));
  if (settings.migrants >= settings.evolve.population_size) s.reject("migrants", "must be smaller than 'population'");
  settings.max_evaluations = std::size_t(s.get_int("max_evaluations"));
  settings.data = load_symreg_data(s.get_section("dataset"));
  settings.anchors = anchors_of(s, *settings.data);
  try {
    gp::validate(settings.evolve);
  } catch (const std::invalid_argument& e) {
    s.reject("operators", std::string("give an invalid search: ") + e.what());
  }
  return settings;
}

JobKind symreg_kind() {
  return {"symreg", "symbolic regression: island-model linear GP, Pareto fronts of error vs shader cost",
          symreg_schema(), make_symreg};
}

}  // namespace pbrfit::jobs::symreg
