// Syntax trees, genBRDF's edits and the generation of an island of edit genomes.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

#include "pbrfit/gp/edit_evolution.hpp"
#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/expression_printer.hpp"
#include "pbrfit/gp/parameter_fit.hpp"
#include "pbrfit/gp/tree_walker.hpp"

using namespace pbrfit;
using namespace pbrfit::gp;

namespace {

const ExpressionNames names{{"x", "y"}, {"p0", "p1"}};

ParsedExpression parsed(const char* text) { return std::get<ParsedExpression>(parse_expression(text, names)); }

SyntaxTree tree(const char* text) {
  const auto p = parsed(text);
  return tree_of(p.program, p.parameter_slots);
}

std::string text_of(const SyntaxTree& t) {
  const auto compiled = compile(t, 2);
  REQUIRE(compiled);
  return print_expression(compiled->program, names, compiled->parameter_slots);
}

EditGrammar grammar() {
  EditGrammar g;
  g.unary = {Opcode::neg, Opcode::sin, Opcode::cos, Opcode::exp, Opcode::sqrt};
  g.binary = {Opcode::add, Opcode::sub, Opcode::mul, Opcode::div, Opcode::min, Opcode::max};
  g.inputs = 2;
  g.parameters = 2;
  g.constants = {1.0, 2.0, std::numbers::pi, 4.0};
  return g;
}

}  // namespace

TEST_CASE("a program expands to a tree in preorder and compiles back to the same function") {
  const SyntaxTree t = tree("a = x * y; sin(a) + a * p0");
  CHECK(t.size() == 10);  // + sin * x y * * x y p0
  CHECK(t.subtree_end(0) == 10);
  CHECK(t.subtree_end(1) == 5);
  CHECK(t.nodes()[9].kind == NodeKind::parameter);
  CHECK(text_of(t) == "t1 = x * y\nsin(t1) + t1 * p0");
  CHECK_THROWS_AS(SyntaxTree({{NodeKind::operation, Opcode::add, 0, 0.0}}), std::invalid_argument);
}

TEST_CASE("each edit kind changes the tree as genBRDF defines it, and any edit applies to any tree") {
  const SyntaxTree t = tree("x * y + p0");  // + * x y p0
  const EditGrammar g = grammar();
  CHECK(text_of(apply_edit(t, {EditKind::swap, 1, 4}, g)) == "p0 + x * y");
  CHECK(apply_edit(t, {EditKind::swap, 1, 2}, g) == t);  // x lies in the product's subtree
  CHECK(text_of(apply_edit(t, {EditKind::remove, 1, 0}, g)) == "1 + p0");
  const auto replaced = apply_edit(t, {EditKind::replace, 0, 0}, g);
  CHECK(replaced.nodes()[0].kind == NodeKind::operation);
  CHECK(replaced.nodes()[0].op != Opcode::add);
  CHECK(arity(replaced.nodes()[0].op) == 2);
  const auto scalar = apply_edit(t, {EditKind::replace, 2, 5}, g);
  CHECK(!(scalar.nodes()[2] == t.nodes()[2]));
  CHECK(scalar.nodes()[2].kind != NodeKind::operation);
  EditGrammar with_bank = g;
  with_bank.codebank = codebank_of(std::vector<SyntaxTree>{tree("cos(x)")});
  CHECK(with_bank.codebank.size() == 2);  // cos(x) and x
  CHECK(text_of(apply_edit(t, {EditKind::insert, 0, 4}, with_bank)) == "x * y + cos(x)");
  RandomStream random(3, 0);
  SyntaxTree walked = t;
  for (int i = 0; i < 2000; ++i) walked = apply_edit(walked, random_edit(random), with_bank);
  CHECK(walked.size() <= with_bank.max_nodes);
}

TEST_CASE("an island's next generation is bred deterministically from tournaments, crossover and one edit each") {
  std::vector<EditIndividual> population;
  RandomStream random(9, 0);
  const auto genomes = initial_genomes(16, random);
  for (std::size_t i = 0; i < genomes.size(); ++i) population.push_back({genomes[i], {double(i), 1.0, 0.0, true}});
  const auto next = breed_island(population, {}, random);
  CHECK(next == breed_island(population, {}, random));
  REQUIRE(next.size() == 16);
  for (const auto& g : next) CHECK(g.size() >= 1);
  // Parents come first and each grew by one edit; with tournaments of 8, good members are chosen most.
  std::size_t from_best_quarter = 0;
  for (std::size_t k = 0; k < 8; ++k) {
    CHECK(next[k].size() == 2);
    for (std::size_t i = 0; i < 4; ++i)
      if (std::equal(genomes[i].begin(), genomes[i].end(), next[k].begin())) ++from_best_quarter;
  }
  CHECK(from_best_quarter >= 6);
  CHECK_THROWS_AS(breed_island(std::span(population).first(3), {}, random), std::invalid_argument);
}

TEST_CASE("parameters are fitted by Nelder-Mead from random starts") {
  Dataset data;
  data.inputs.resize(50, 2);
  data.target.resize(50);
  for (int r = 0; r < 50; ++r) {
    data.inputs(r, 0) = r / 49.0;
    data.inputs(r, 1) = 0.0;
    data.target[r] = 0.7 * std::exp(-3.0 * data.inputs(r, 0));
  }
  const auto model = parsed("p0 * exp(-(p1 * x))");
  BatchInterpreter<double> interpreter(data);
  ParameterFitOptions options;
  options.start_upper = 4.0;
  const auto fit = fit_parameters(model.program, model.parameter_slots, interpreter, options, RandomStream(1, 0));
  CHECK(fit.error < 1e-6);
  CHECK(std::abs(fit.parameters[0] - 0.7) < 1e-4);
  CHECK(std::abs(fit.parameters[1] - 3.0) < 1e-3);
  CHECK(fit.evaluations <= options.starts * options.evaluations_per_start);

  SECTION("a warm start begins the first search at the previous fit's point") {
    options.starts = 1;
    options.evaluations_per_start = 1;
    const std::vector<double> previous = {0.7, 3.0};
    const auto warm = fit_parameters(model.program, model.parameter_slots, interpreter, options, RandomStream(1, 0), previous);
    CHECK(warm.error < 1e-6);
    CHECK(warm.parameters == previous);
    options.warm_start = false;
    const auto cold = fit_parameters(model.program, model.parameter_slots, interpreter, options, RandomStream(1, 0), previous);
    CHECK(cold.error > 1e-3);
    const auto unseeded = fit_parameters(model.program, model.parameter_slots, interpreter, options, RandomStream(1, 0));
    CHECK(cold.parameters == unseeded.parameters);
  }
}
