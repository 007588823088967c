#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstddef>
#include <vector>

#include "gp_test_support.hpp"
#include "pbrfit/gp/cost_model.hpp"
#include "pbrfit/gp/variation.hpp"
#include "pbrfit/gp/live_code.hpp"
#include "pbrfit/gp/program_builder.hpp"
#include "pbrfit/gp/tree_walker.hpp"

using namespace pbrfit::gp;
using pbrfit::RandomStream;

namespace {

double at(const Program& program, double x, double y) {
  const double row[2] = {x, y};
  return walk_tree<double>(program, std::span<const double>(row, 2));
}

}  // namespace

TEST_CASE("Random programs are valid and draw only the shape's operators", "[gp]") {
  ProgramShape shape = gp_test::wide_shape(2);
  shape.operators = koza_operators();
  for (std::uint64_t i = 0; i < 500; ++i) {
    const Program program = gp_test::random_program(shape, 1, i);
    REQUIRE(is_valid(program, 2));
    CHECK(program.length >= shape.initial_min_length);
    CHECK(program.length <= shape.initial_max_length);
    for (const Instruction& instruction : program.instructions()) CHECK(shape.operators.contains(instruction.op));
  }
}

TEST_CASE("Every mutation keeps programs valid and within the maximum length", "[gp]") {
  const ProgramShape shape = gp_test::wide_shape(2);
  const MutationOptions options;
  std::size_t changed = 0;
  for (std::uint64_t i = 0; i < 400; ++i) {
    Program program = gp_test::random_program(shape, 2, i);
    for (int kind = 0; kind < 5; ++kind) {
      RandomStream random(3, i, static_cast<std::uint64_t>(kind));
      const Program child = mutate(program, static_cast<MutationKind>(kind), shape, options, random);
      CAPTURE(i, kind);
      REQUIRE(is_valid(child, 2));
      CHECK(child.length <= shape.max_length);
      changed += !(child == program);
      program = child;  // chains of mutations, too
    }
  }
  CHECK(changed > 1800);  // of 2000: a mutation of a live instruction nearly always changes something
}

TEST_CASE("Insertion wraps a live operand and deletion bypasses a live instruction", "[gp]") {
  ProgramShape shape;
  shape.operators = {Opcode::sin};
  shape.input_count = 2;
  shape.reference_probability = 0.0;
  ProgramBuilder builder;
  const Argument sum = builder.append(Opcode::add, {input_argument(0), input_argument(1)});
  const Program program = builder.finish(builder.append(Opcode::mul, {sum, input_argument(0)}));
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    RandomStream random(4, seed);
    const Program longer = mutate(program, MutationKind::insertion, shape, {}, random);
    REQUIRE(is_valid(longer, 2));
    CHECK(longer.length == 3);
    CHECK(live_length(longer) == 3);  // the new instruction is live at once
    const Program shorter = mutate(program, MutationKind::deletion, shape, {}, random);
    REQUIRE(is_valid(shorter, 2));
    CHECK(program_cost(shorter, gcn_cost_table()) == 1.0);  // a bypassed output becomes a free identity
    // Bypassing add gives x * x; bypassing the output mul leaves x + y.
    const double value = at(shorter, 0.5, 2.0);
    CHECK((value == 0.25 || value == 2.5));
  }
}

TEST_CASE("Crossovers keep references earlier and lengths bounded", "[gp]") {
  const ProgramShape shape = gp_test::wide_shape(2);
  for (std::uint64_t i = 0; i < 500; ++i) {
    const Program mother = gp_test::random_program(shape, 5, i);
    const Program father = gp_test::random_program(shape, 6, i);
    RandomStream random(7, i);
    for (std::size_t max_length : {std::size_t{40}, std::size_t{12}}) {
      const Program by_string = string_crossover(mother, father, max_length, random);
      const Program by_subgraph = subgraph_crossover(mother, father, max_length, random);
      CAPTURE(i, max_length);
      REQUIRE(is_valid(by_string, 2));
      REQUIRE(is_valid(by_subgraph, 2));
      CHECK((by_string.length <= max_length || by_string == mother));
      CHECK((by_subgraph.length <= max_length || by_subgraph == mother));
    }
  }
}

TEST_CASE("Subgraph crossover transplants the father's subexpression into the mother", "[gp]") {
  ProgramBuilder mother_builder;  // sin(x) * y
  const Argument s = mother_builder.append(Opcode::sin, {input_argument(0)});
  const Program mother = mother_builder.finish(mother_builder.append(Opcode::mul, {s, input_argument(1)}));
  ProgramBuilder father_builder;  // exp(x + 2) - y
  const Argument t = father_builder.append(Opcode::add, {input_argument(0), constant_argument(2.0)});
  const Argument e = father_builder.append(Opcode::exp, {t});
  const Program father = father_builder.finish(father_builder.append(Opcode::sub, {e, input_argument(1)}));
  bool saw_exp_times_y = false;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    RandomStream random(8, seed);
    const Program child = subgraph_crossover(mother, father, 64, random);
    REQUIRE(is_valid(child, 2));
    saw_exp_times_y = saw_exp_times_y || std::abs(at(child, 0.3, 1.7) - std::exp(2.3) * 1.7) < 1e-12;
  }
  CHECK(saw_exp_times_y);  // sin(x) replaced by exp(x + 2)
}

TEST_CASE("String crossover joins the mother's head to the father's tail", "[gp]") {
  ProgramBuilder a;  // 0: x + y, 1: sin(0)
  const Program mother =
      a.finish(a.append(Opcode::sin, {a.append(Opcode::add, {input_argument(0), input_argument(1)})}));
  ProgramBuilder b;  // 0: x * y, 1: cos(0)
  const Program father =
      b.finish(b.append(Opcode::cos, {b.append(Opcode::mul, {input_argument(0), input_argument(1)})}));
  bool saw_cos_of_sum = false;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    RandomStream random(9, seed);
    const Program child = string_crossover(mother, father, 64, random);
    saw_cos_of_sum = saw_cos_of_sum || at(child, 0.25, 0.5) == std::cos(0.75);
  }
  CHECK(saw_cos_of_sum);
}
