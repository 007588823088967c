#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <vector>

#include "block_schedule.hpp"
#include "gp_test_support.hpp"
#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/cost_model.hpp"
#include "pbrfit/gp/fitness_evaluator.hpp"
#include "pbrfit/gp/live_code.hpp"
#include "pbrfit/gp/program_builder.hpp"
#include "pbrfit/gp/tree_walker.hpp"

using namespace pbrfit::gp;

namespace {

// Two full blocks and a partial one.
constexpr std::size_t mixed_rows = 2 * block_rows + 44;
const Dataset& mixed_inputs() {
  static const Dataset dataset = gp_test::sampled_dataset(mixed_rows, 3, -2.0, 2.0, [](auto) { return 0.0; });
  return dataset;
}

template <class T>
bool close(T batch, T walker, double tolerance) {
  if (std::isnan(batch) || std::isnan(walker)) return std::isnan(batch) && std::isnan(walker);
  if (std::isinf(batch) || std::isinf(walker))
    return batch == walker || std::abs(double(batch) - double(walker)) > 1e30;
  return std::abs(double(batch) - double(walker)) <= tolerance * (1.0 + std::abs(double(walker)));
}

// Counts rows where the batch interpreter and the tree walker disagree: bitwise for arithmetic-only
// programs, within `tolerance` otherwise.
template <class T>
std::size_t disagreements(const Program& program, double tolerance) {
  const Dataset& dataset = mixed_inputs();
  BatchInterpreter<T> interpreter(dataset);
  std::vector<T> batch(dataset.rows());
  std::vector<T> walked(dataset.rows());
  interpreter.evaluate(program, batch);
  walk_tree<T>(program, dataset, walked);
  bool exact_ops = true;
  for (const Instruction& instruction : program.instructions()) {
    const Opcode op = instruction.op;
    exact_ops = exact_ops && (op <= Opcode::neg || op == Opcode::saturate);
  }
  std::size_t count = 0;
  for (std::size_t r = 0; r < batch.size(); ++r) {
    const bool same = exact_ops ? std::memcmp(&batch[r], &walked[r], sizeof(T)) == 0 ||
                                      (batch[r] != batch[r] && walked[r] != walked[r])
                                : close(batch[r], walked[r], tolerance);
    count += !same;
  }
  return count;
}

}  // namespace

// In every kernel set: arithmetic (fma among it) bitwise as the tree walker, so no set contracts a * b + c.
TEST_CASE("The batch interpreter agrees with the tree walker on random programs, in every kernel set", "[gp]") {
  for (const auto set : pbrfit::kernel_sets_available()) {
  const gp_test::KernelSetScope scope(set);
  CAPTURE(pbrfit::kernel_set_name(set));
  ProgramShape shape = gp_test::wide_shape(3);
  ProgramShape arithmetic = shape;
  arithmetic.operators = {Opcode::add, Opcode::sub, Opcode::mul, Opcode::div, Opcode::fma,
                          Opcode::min, Opcode::max, Opcode::abs, Opcode::neg, Opcode::saturate};
  std::size_t float_rows_off = 0;
  std::size_t double_rows_off = 0;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const Program exact = gp_test::random_program(arithmetic, seed, 1);
    CAPTURE(seed);
    CHECK(disagreements<float>(exact, 0.0) == 0);
    CHECK(disagreements<double>(exact, 0.0) == 0);
    const Program any = gp_test::random_program(shape, seed, 2);
    float_rows_off += disagreements<float>(any, 1e-3);
    double_rows_off += disagreements<double>(any, 1e-9);
  }
  // Vectorized transcendentals differ from the C library's by ulps, which deep compositions may amplify.
  CHECK(float_rows_off <= 200 * mixed_rows / 1000);
  CHECK(double_rows_off <= 200 * mixed_rows / 1000);
  }
}

TEST_CASE("Every operator matches its scalar semantics over one block, in every kernel set", "[gp]") {
  for (const auto set : pbrfit::kernel_sets_available())
  for (std::size_t k = 0; k < opcode_count; ++k) {
    const gp_test::KernelSetScope scope(set);
    CAPTURE(pbrfit::kernel_set_name(set));
    const auto op = static_cast<Opcode>(k);
    ProgramBuilder builder;
    const Argument a = input_argument(0);
    const Argument b = input_argument(1);
    const Argument c = input_argument(2);
    const Argument all[3] = {a, b, c};
    const Program program = builder.finish(builder.append(op, all, static_cast<std::size_t>(arity(op))));
    CAPTURE(name(op));
    CHECK(disagreements<float>(program, 1e-6) == 0);
    CHECK(disagreements<double>(program, 1e-14) == 0);
  }
}

// Binary operators read a constant operand once instead of its block: the same values either way.
TEST_CASE("Constant operands, first, second or both, give the scalar semantics in every kernel set", "[gp]") {
  const Argument x = input_argument(0);
  const Argument y = input_argument(1);
  for (const double value : {0.75, -1.25, 0.0}) {
    const Argument k = constant_argument(value);
    const Argument patterns[][3] = {{k, y, x}, {x, k, y}, {k, k, k}, {x, y, k}};
    for (const auto set : pbrfit::kernel_sets_available())
      for (std::size_t op_index = 0; op_index < opcode_count; ++op_index)
        for (const auto& pattern : patterns) {
          const gp_test::KernelSetScope scope(set);
          const auto op = static_cast<Opcode>(op_index);
          ProgramBuilder builder;
          const Program program = builder.finish(builder.append(op, pattern, static_cast<std::size_t>(arity(op))));
          CAPTURE(pbrfit::kernel_set_name(set), name(op), value, &pattern - patterns);
          CHECK(disagreements<float>(program, 1e-6) == 0);
          CHECK(disagreements<double>(program, 1e-14) == 0);
        }
  }
}

namespace {

// The steps the interpreter runs for `program` over the mixed inputs, after fusing pairs.
std::size_t scheduled_steps(const Program& program) {
  const Eigen::ArrayXXf columns = mixed_inputs().inputs.cast<float>();
  std::vector<float> slots(max_program_length * block_rows);
  std::vector<float> constants(max_program_length * max_operands * block_rows);
  return detail::schedule_blocks<float>(program, columns, slots, constants, block_rows).step_count;
}

}  // namespace

// A step and the next fuse when the next is the only reader of its result, reading it once; the fused
// pair computes what the two steps did, bitwise, in every kernel set.
TEST_CASE("Arithmetic pairs fuse only where the next step alone reads the result, with the same values", "[gp]") {
  const Argument x = input_argument(0);
  const Argument y = input_argument(1);
  const Argument z = input_argument(2);
  struct Case {
    const char* what;
    Program program;
    std::size_t steps;
  };
  std::vector<Case> cases;
  {
    ProgramBuilder b;
    const Argument left = b.append(Opcode::mul, {b.append(Opcode::add, {x, y}), z});   // fused, left
    const Argument right = b.append(Opcode::div, {z, b.append(Opcode::sub, {y, x})});  // fused, right
    cases.push_back({"two pairs and their sum", b.finish(b.append(Opcode::add, {left, right})), 3});
  }
  {
    ProgramBuilder b;
    const Argument sum = b.append(Opcode::add, {x, y});
    cases.push_back({"a result read twice", b.finish(b.append(Opcode::mul, {sum, sum})), 2});
  }
  {
    ProgramBuilder b;
    const Argument alias = b.append(Opcode::identity, {b.append(Opcode::add, {x, y})});
    cases.push_back({"through an identity", b.finish(b.append(Opcode::mul, {alias, z})), 1});
  }
  {
    ProgramBuilder b;
    cases.push_back({"into a transcendental", b.finish(b.append(Opcode::exp, {b.append(Opcode::add, {x, y})})), 2});
  }
  {
    ProgramBuilder b;
    const Argument first = b.append(Opcode::add, {x, y});
    const Argument second = b.append(Opcode::mul, {z, x});
    cases.push_back({"a reader further on", b.finish(b.append(Opcode::sub, {first, second})), 2});
  }
  {
    ProgramBuilder b;
    const Argument k = constant_argument(0.5);
    const Argument chain = b.append(Opcode::div, {k, b.append(Opcode::mul, {b.append(Opcode::sub, {x, k}), y})});
    cases.push_back({"a chain of three, with constants", b.finish(b.append(Opcode::add, {chain, z})), 2});
  }
  for (const Case& c : cases) {
    CAPTURE(c.what);
    CHECK(scheduled_steps(c.program) == c.steps);
    for (const auto set : pbrfit::kernel_sets_available()) {
      const gp_test::KernelSetScope scope(set);
      CAPTURE(pbrfit::kernel_set_name(set));
      CHECK(disagreements<float>(c.program, 1e-6) == 0);  // bitwise where every operator is exact
      CHECK(disagreements<double>(c.program, 1e-14) == 0);
    }
  }
}

namespace {

// The schedule of `program` over the mixed inputs, with the slot memory it points into.
struct ScheduledProgram {
  std::vector<float> slots = std::vector<float>(max_program_length * block_rows);
  std::vector<float> constants = std::vector<float>(max_program_length * max_operands * block_rows);
  detail::BlockSchedule<float> schedule;

  explicit ScheduledProgram(const Program& program) {
    const Eigen::ArrayXXf columns = mixed_inputs().inputs.cast<float>();
    schedule = detail::schedule_blocks<float>(program, columns, slots, constants, block_rows);
  }
  std::size_t slots_used() const {
    std::vector<const float*> outs;
    for (std::size_t s = 0; s < schedule.step_count; ++s) outs.push_back(schedule.steps[s].out);
    std::sort(outs.begin(), outs.end());
    return static_cast<std::size_t>(std::unique(outs.begin(), outs.end()) - outs.begin());
  }
  // Whether some step writes one of the operands it reads (its arity's, and a fused pair's third).
  bool writes_an_operand() const {
    for (std::size_t s = 0; s < schedule.step_count; ++s) {
      const auto& step = schedule.steps[s];
      const int read = step.second != Opcode::identity ? 3 : arity(step.op);
      for (int j = 0; j < read; ++j)
        if (step.operands[static_cast<std::size_t>(j)].base == step.out) return true;
    }
    return false;
  }
};

}  // namespace

// A result's slot is reused once no later step reads it, so a tree needs about as many slots as it is deep.
TEST_CASE("Steps reuse the slots of results no later step reads, never writing an operand", "[gp]") {
  const Argument x = input_argument(0);
  const Argument y = input_argument(1);
  {
    ProgramBuilder b;  // a chain of 40 steps, each reading the last: two slots, alternately
    Argument chain = x;
    for (int i = 0; i < 40; ++i) chain = b.append(i % 2 ? Opcode::abs : Opcode::neg, {chain});
    const Program program = b.finish(chain);
    const ScheduledProgram scheduled(program);
    CHECK(scheduled.schedule.step_count == 40);
    CHECK(scheduled.slots_used() == 2);
    CHECK_FALSE(scheduled.writes_an_operand());
    CHECK(disagreements<float>(program, 0.0) == 0);
  }
  {
    // A balanced tree of 31 min/max steps over 32 leaf steps (depth 5), in post-order: the deepest step
    // of the last subtree runs while 4 results wait, one per level above it, on its 2 leaves, and writes a
    // slot of its own: 7 slots for 63 steps.
    ProgramBuilder post;
    auto leaf = [&](std::size_t i) { return post.append(Opcode::neg, {i % 2 ? x : y}); };
    auto tree = [&](auto&& self, std::size_t first, std::size_t count, bool use_min) -> Argument {
      if (count == 1) return leaf(first);
      const Argument left = self(self, first, count / 2, !use_min);
      const Argument right = self(self, first + count / 2, count / 2, !use_min);
      return post.append(use_min ? Opcode::min : Opcode::max, {left, right});
    };
    const Program program = post.finish(tree(tree, 0, 32, true));
    const ScheduledProgram scheduled(program);
    CHECK(scheduled.schedule.step_count == 63);
    CHECK(scheduled.slots_used() == 7);
    CHECK_FALSE(scheduled.writes_an_operand());
    CHECK(disagreements<float>(program, 0.0) == 0);
  }
  for (std::uint64_t seed = 0; seed < 200; ++seed) {  // random programs, fused pairs among them
    CAPTURE(seed);
    const ScheduledProgram scheduled(gp_test::random_program(gp_test::wide_shape(3), seed, 2));
    CHECK_FALSE(scheduled.writes_an_operand());
    CHECK(scheduled.slots_used() <= scheduled.schedule.step_count);
  }
}

// A fused pair reads a constant operand once, wherever it stands: the same values, bitwise.
TEST_CASE("Fused pairs with constant operands give the scalar semantics in every kernel set", "[gp]") {
  const Opcode arithmetic[] = {Opcode::add, Opcode::sub, Opcode::mul, Opcode::div};
  const Argument x = input_argument(0);
  const Argument y = input_argument(1);
  const Argument z = input_argument(2);
  const Argument k = constant_argument(-0.625);
  const Argument m = constant_argument(1.75);
  // (a, b, c) of second(first(a, b), c): constants first, second, third and in pairs.
  const Argument patterns[][3] = {{k, y, z}, {x, k, z}, {x, y, k}, {k, y, m}, {x, k, m}, {k, m, z}};
  for (const auto set : pbrfit::kernel_sets_available())
    for (const Opcode first : arithmetic)
      for (const Opcode second : arithmetic)
        for (const bool left : {true, false})
          for (const auto& pattern : patterns) {
            const gp_test::KernelSetScope scope(set);
            ProgramBuilder b;
            const Argument inner = b.append(first, {pattern[0], pattern[1]});
            const Program program =
                b.finish(left ? b.append(second, {inner, pattern[2]}) : b.append(second, {pattern[2], inner}));
            CAPTURE(pbrfit::kernel_set_name(set), name(first), name(second), left, &pattern - patterns);
            CHECK(scheduled_steps(program) == 1);
            CHECK(disagreements<float>(program, 0.0) == 0);
            CHECK(disagreements<double>(program, 0.0) == 0);
          }
}

TEST_CASE("Introns are skipped and pruning keeps the function bitwise", "[gp]") {
  ProgramBuilder builder;
  const Argument x = input_argument(0);
  builder.append(Opcode::exp, {x});                                                    // 0: intron
  const Argument square = builder.append(Opcode::mul, {x, x});                         // 1
  builder.append(Opcode::log, {square});                                               // 2: intron reading a live one
  const Argument sum = builder.append(Opcode::add, {square, constant_argument(1.5)});  // 3
  const Program program = builder.finish(sum);
  CHECK(live_length(program) == 2);
  CHECK(live_instructions(program).to_ulong() == 0b1010);
  const Program pruned = without_introns(program);
  REQUIRE(is_valid(pruned, 1));
  CHECK(pruned.length == 2);
  CHECK(program_cost(program, gcn_cost_table()) == 2.0);  // introns cost nothing
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    const Program random = gp_test::random_program(gp_test::wide_shape(3), seed, 3);
    const Program compact = without_introns(random);
    REQUIRE(is_valid(compact, 3));
    CHECK(compact.length == live_length(random));
    BatchInterpreter<float> interpreter(mixed_inputs());
    std::vector<float> full(mixed_rows);
    std::vector<float> short_form(mixed_rows);
    interpreter.evaluate(random, full);
    interpreter.evaluate(compact, short_form);
    CHECK(std::memcmp(full.data(), short_form.data(), full.size() * sizeof(float)) == 0);
  }
}

TEST_CASE("Poles, overflow and NaN give the worst error, never NaN or a crash", "[gp]") {
  const Dataset dataset = gp_test::sampled_dataset(200, 1, -1.0, 1.0, [](auto x) { return x[0]; });
  Dataset with_zero = dataset;
  with_zero.inputs(17, 0) = 0.0;
  const Argument x = input_argument(0);
  const auto single = [&](Opcode op, std::initializer_list<Argument> arguments) {
    ProgramBuilder builder;
    return builder.finish(builder.append(op, arguments));
  };
  ProgramBuilder overflow;
  const Argument big = overflow.append(Opcode::exp, {constant_argument(400.0)});
  const Program huge = overflow.finish(overflow.append(Opcode::mul, {big, big}));
  ProgramBuilder nan_builder;
  const Argument pole = nan_builder.append(Opcode::div, {x, x});  // 0/0 at row 17
  const Program hidden_nan = nan_builder.finish(nan_builder.append(Opcode::min, {pole, constant_argument(2.0)}));
  const std::vector<Program> poisoned{single(Opcode::div, {constant_argument(1.0), x}),
                                      single(Opcode::log, {x}),
                                      single(Opcode::rsqrt, {x}),
                                      huge,
                                      hidden_nan,
                                      single(Opcode::pow, {x, constant_argument(-1.0)})};
  for (Precision precision : {Precision::float32, Precision::float64}) {
    FitnessOptions options;
    options.precision = precision;
    FitnessEvaluator evaluator(with_zero, options);
    for (const Program& program : poisoned) {
      const Fitness fitness = evaluator(program);
      CHECK(fitness.evaluated);
      CHECK(fitness.error == worst_error);
    }
    CHECK(evaluator(single(Opcode::sqrt, {x})).error < 2.0);  // protected: sqrt(|x|)
    CHECK(evaluator.evaluations() == poisoned.size() + 1);
  }
}

TEST_CASE("Error measures: RMSE, max abs and relative, weighted", "[gp]") {
  Dataset dataset;
  dataset.inputs = Eigen::ArrayXXd(4, 1);
  dataset.inputs << 1.0, 2.0, 3.0, 4.0;
  dataset.target = Eigen::ArrayXd(4);
  dataset.target << 1.0, 2.0, 2.0, 8.0;  // residuals of y = x: 0, 0, 1, -4
  ProgramBuilder builder;
  const Program identity = builder.finish(input_argument(0));
  CHECK(BatchInterpreter<double>(dataset).error(identity) == std::sqrt(17.0 / 4.0));
  CHECK(BatchInterpreter<float>(dataset, {ErrorMeasure::max_abs}).error(identity) == 4.0);
  CHECK(BatchInterpreter<double>(dataset, {ErrorMeasure::relative}).error(identity) == std::sqrt((0.25 + 0.25) / 4.0));
  dataset.weights = Eigen::ArrayXd(4);
  dataset.weights << 1.0, 1.0, 2.0, 0.0;
  CHECK(BatchInterpreter<double>(dataset).error(identity) == std::sqrt(2.0 / 4.0));
}

namespace {

// error_sums.hpp's order, written out row by row: four partial sums, row r in lane r mod 4 except the rows
// beyond the last multiple of 4 (lane 0, in order), then (s0 + s1) + (s2 + s3); the maximum likewise.
// Blocks hold a multiple of 4 rows, so a block's lanes are the rows' lanes.
template <class T>
double error_in_documented_order(const Dataset& dataset, ErrorMeasure measure) {
  const std::size_t rows = static_cast<std::size_t>(dataset.target.size());
  double squares[4] = {0.0, 0.0, 0.0, 0.0};
  double max_abs[4] = {0.0, 0.0, 0.0, 0.0};
  const double weight_sum = dataset.weights.sum();  // Eigen's reduction, as the interpreter's
  for (std::size_t r = 0; r < rows; ++r) {
    const auto i = static_cast<Eigen::Index>(r);
    const std::size_t lane = r < rows - rows % 4 ? r % 4 : 0;
    const double target = dataset.target[i];
    const double scale = measure == ErrorMeasure::relative ? 1.0 / std::max(std::abs(target), ErrorOptions{}.relative_floor) : 1.0;
    const double residual = static_cast<double>(static_cast<T>(dataset.inputs(i, 0))) - target;
    const double scaled = residual * scale;
    squares[lane] += dataset.weights[i] * scaled * scaled;
    max_abs[lane] = std::max(max_abs[lane], std::abs(residual));
  }
  if (measure == ErrorMeasure::max_abs) return std::max(std::max(max_abs[0], max_abs[1]), std::max(max_abs[2], max_abs[3]));
  return std::sqrt(((squares[0] + squares[1]) + (squares[2] + squares[3])) / weight_sum);
}

}  // namespace

// The error's sums run as vector code over four lanes; their order is part of the determinism contract (a
// sum in another order, or over eight lanes, rounds differently), so every error is that order's, bitwise.
TEST_CASE("The error sums rows in the documented order, bitwise, for every measure and type", "[gp]") {
  ProgramBuilder builder;
  const Program identity = builder.finish(input_argument(0));
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    CAPTURE(seed);
    // Weights over four orders of magnitude, so that summing in another order rounds differently.
    Dataset dataset = gp_test::sampled_dataset(mixed_rows + 3, 1, -3.0, 3.0, [](auto x) { return std::sin(3.0 * x[0]); }, seed);
    pbrfit::RandomStream random(seed, 1);
    dataset.weights = Eigen::ArrayXd(dataset.target.size());
    for (Eigen::Index i = 0; i < dataset.weights.size(); ++i) dataset.weights[i] = std::exp(10.0 * random.uniform());
    for (const ErrorMeasure measure : {ErrorMeasure::rmse, ErrorMeasure::max_abs, ErrorMeasure::relative}) {
      CAPTURE(name(measure));
      CHECK(BatchInterpreter<float>(dataset, {measure}).error(identity) == error_in_documented_order<float>(dataset, measure));
      CHECK(BatchInterpreter<double>(dataset, {measure}).error(identity) == error_in_documented_order<double>(dataset, measure));
    }
  }
}

TEST_CASE("The cost counts live operators from the table and the piecewise ones", "[gp]") {
  ProgramBuilder builder;
  const Argument x = input_argument(0);
  const Argument q = builder.append(Opcode::div, {x, constant_argument(3.0)});    // 5
  const Argument e = builder.append(Opcode::exp2, {q});                           // 4
  const Argument m = builder.append(Opcode::max, {e, x});                         // 1, piecewise
  const Program program = builder.finish(builder.append(Opcode::saturate, {m}));  // 1, piecewise
  CostTable table = gcn_cost_table();
  CHECK(program_cost(program, table) == 11.0);
  CHECK(piecewise_count(program) == 2);
  table.piecewise_penalty = 10.0;
  CHECK(program_cost(program, table) == 31.0);
}

namespace {

// Distance in units in the last place between two finite values of one type (0 when both are NaN).
template <class T>
double ulps_apart(T x, T y) {
  if (std::isnan(x) || std::isnan(y)) return std::isnan(x) && std::isnan(y) ? 0.0 : 1e300;
  if (x == y) return 0.0;
  return std::abs(double(x) - double(y)) / double(std::nextafter(std::abs(y), std::numeric_limits<T>::infinity()) - std::abs(y));
}

struct SetDifference {
  std::size_t rows_differing = 0;
  double max_ulps = 0.0;
};

// One operator over the mixed inputs in `set` against the generic set.
template <class T>
SetDifference set_difference(pbrfit::KernelSet set, Opcode op) {
  ProgramBuilder builder;
  const Argument all[3] = {input_argument(0), input_argument(1), input_argument(2)};
  const Program program = builder.finish(builder.append(op, all, static_cast<std::size_t>(arity(op))));
  const Dataset& dataset = mixed_inputs();
  std::vector<T> generic(dataset.rows()), other(dataset.rows());
  {
    const gp_test::KernelSetScope scope(pbrfit::KernelSet::generic);
    BatchInterpreter<T>(dataset).evaluate(program, generic);
  }
  {
    const gp_test::KernelSetScope scope(set);
    BatchInterpreter<T>(dataset).evaluate(program, other);
  }
  SetDifference d;
  for (std::size_t r = 0; r < generic.size(); ++r) {
    const bool same = std::memcmp(&generic[r], &other[r], sizeof(T)) == 0;
    d.rows_differing += !same;
    d.max_ulps = std::max(d.max_ulps, ulps_apart(other[r], generic[r]));
  }
  return d;
}

}  // namespace

// kernel_set.hpp: sets differ in transcendental results only (sqrt and rsqrt excepted), by a few ulps; and a set other than generic
// runs code of its own (its FMA polynomials round differently from the generic ones somewhere).
TEST_CASE("Kernel sets differ from the generic one only in transcendentals, by a few ulps", "[gp]") {
  for (const auto set : pbrfit::kernel_sets_available()) {
    CAPTURE(pbrfit::kernel_set_name(set));
    std::size_t transcendental_rows_differing = 0;
    for (std::size_t k = 0; k < opcode_count; ++k) {
      const auto op = static_cast<Opcode>(k);
      CAPTURE(name(op));
      const auto f = set_difference<float>(set, op);
      const auto d = set_difference<double>(set, op);
      if (op <= Opcode::neg || op == Opcode::saturate || op == Opcode::sqrt || op == Opcode::rsqrt) {
        CHECK(f.rows_differing == 0);
        CHECK(d.rows_differing == 0);
      } else {
        // pow is exp(b log2|a| ln2): the two functions' differences add up.
        const double bound = op == Opcode::pow ? 8.0 : 4.0;
        CHECK(f.max_ulps <= bound);
        CHECK(d.max_ulps <= bound);
        transcendental_rows_differing += f.rows_differing + d.rows_differing;
      }
    }
    if (set == pbrfit::KernelSet::generic) CHECK(transcendental_rows_differing == 0);
    else CHECK(transcendental_rows_differing > 0);
  }
}

// block_vector_math.hpp: Eigen 3.4 computes tan, asin, acos and atan by the C library, one lane at a time,
// which would give the generic set's values; the avx2 and avx512 sets take glibc's vector versions, whose
// polynomials round differently somewhere in every one of them.
TEST_CASE("The avx2 and avx512 sets compute tan, asin, acos and atan by vector code, not lane by lane", "[gp]") {
  for (const auto set : pbrfit::kernel_sets_available()) {
    if (set == pbrfit::KernelSet::generic) continue;
    CAPTURE(pbrfit::kernel_set_name(set));
    for (const Opcode op : {Opcode::tan, Opcode::asin, Opcode::acos, Opcode::atan}) {
      CAPTURE(name(op));
      CHECK(set_difference<float>(set, op).rows_differing > 0);
      CHECK(set_difference<double>(set, op).rows_differing > 0);
    }
  }
}

namespace {

// `dataset` with `shift` rows of zeros before its own.
Dataset shifted(const Dataset& dataset, Eigen::Index shift) {
  Dataset out;
  out.inputs = Eigen::MatrixXd::Zero(dataset.inputs.rows() + shift, dataset.inputs.cols());
  out.inputs.bottomRows(dataset.inputs.rows()) = dataset.inputs;
  out.target = Eigen::VectorXd::Zero(dataset.target.size() + shift);
  out.target.tail(dataset.target.size()) = dataset.target;
  return out;
}

// Rows of `op` over the mixed inputs that differ bitwise when the same inputs sit `shift` rows later.
template <class T>
std::size_t rows_moved_by_shift(Opcode op, Eigen::Index shift) {
  ProgramBuilder builder;
  const Argument all[3] = {input_argument(0), input_argument(1), input_argument(2)};
  const Program program = builder.finish(builder.append(op, all, static_cast<std::size_t>(arity(op))));
  const Dataset& dataset = mixed_inputs();
  const Dataset later = shifted(dataset, shift);
  std::vector<T> here(dataset.rows()), there(later.rows());
  BatchInterpreter<T>(dataset).evaluate(program, here);
  BatchInterpreter<T>(later).evaluate(program, there);
  std::size_t count = 0;
  for (std::size_t r = 0; r < here.size(); ++r)
    count += std::memcmp(&here[r], &there[r + static_cast<std::size_t>(shift)], sizeof(T)) != 0;
  return count;
}

}  // namespace

// Threads and ranks split rows differently and buffers land at different addresses: a row's value must
// not depend on where in a block, or at what alignment, its inputs sit (vector and scalar code paths of a
// transcendental round differently).
TEST_CASE("A row's value depends on its inputs only, not on its place in the block, in every kernel set", "[gp]") {
  for (const auto set : pbrfit::kernel_sets_available())
    for (std::size_t k = 0; k < opcode_count; ++k)
      for (const Eigen::Index shift : {1, 3, 7, 13}) {
        const gp_test::KernelSetScope scope(set);
        const auto op = static_cast<Opcode>(k);
        CAPTURE(pbrfit::kernel_set_name(set), name(op), shift);
        CHECK(rows_moved_by_shift<float>(op, shift) == 0);
        CHECK(rows_moved_by_shift<double>(op, shift) == 0);
      }
}
