// Throughput of the GP interpreters, Operon's protocol: random expression trees of 1 to 64 nodes (uniform
// sizes; a node is an operator, an input or a constant, as in a tree), evaluated over 12,800 rows of 10
// uniform inputs in [-1, 1] on one core. Reports node-rows per second (tree nodes x rows / seconds) for
// the batch interpreter (float and double) and the per-row tree walker, with arithmetic only (+ - * /)
// with transcendentals (+ - * / exp log sin cos sqrt), and with genBRDF's trigonometric operators
// (+ - * / tan asin acos atan: glibc's vector versions in the avx2 and avx512 sets, the C library's scalar
// ones in the generic set), in every kernel set the machine has (core/kernel_set.hpp).
//   bench_gp_interpreter [expressions=1000] [walker_expressions=200] [repeats=3]
//                        [operators=all|arithmetic|transcendental|trigonometric]
// The tree walker runs on the first walker_expressions expressions (it is ~30x slower); the rates are
// per node-row, so they compare directly. Each measurement is the best of `repeats` passes.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/program_builder.hpp"
#include "pbrfit/gp/tree_walker.hpp"

using namespace pbrfit::gp;

namespace {

constexpr std::size_t row_count = 12'800;
constexpr std::size_t input_count = 10;
constexpr std::size_t max_nodes = 64;

struct Expression {
  Program program;
  std::size_t nodes = 0;
};

Argument leaf(pbrfit::RandomStream& random) {
  if (random.uniform() < 0.3) return constant_argument(2.0 * random.uniform() - 1.0);
  return input_argument(random.below(input_count));
}

// A random tree of `nodes` nodes (one less when only binary operators fit), appended to `builder` in
// post-order; `made` counts the nodes.
Argument grow(ProgramBuilder& builder, std::size_t nodes, const std::vector<Opcode>& ops, pbrfit::RandomStream& random,
              std::size_t& made) {
  std::vector<Opcode> fitting;
  for (Opcode op : ops) {
    if (static_cast<std::size_t>(arity(op)) <= nodes - 1) fitting.push_back(op);
  }
  ++made;
  if (fitting.empty()) return leaf(random);
  const Opcode op = fitting[random.below(fitting.size())];
  if (arity(op) == 1) return builder.append(op, {grow(builder, nodes - 1, ops, random, made)});
  const std::size_t left = 1 + random.below(nodes - 2);
  const Argument a = grow(builder, left, ops, random, made);
  const Argument b = grow(builder, nodes - 1 - left, ops, random, made);
  return builder.append(op, {a, b});
}

std::vector<Expression> random_expressions(std::size_t count, const std::vector<Opcode>& ops, std::uint64_t seed) {
  std::vector<Expression> expressions(count);
  for (std::size_t e = 0; e < count; ++e) {
    pbrfit::RandomStream random(seed, e);
    ProgramBuilder builder;
    const std::size_t nodes = 1 + random.below(max_nodes);
    expressions[e].program = builder.finish(grow(builder, nodes, ops, random, expressions[e].nodes));
  }
  return expressions;
}

Dataset random_dataset() {
  Dataset dataset;
  dataset.inputs.resize(row_count, input_count);
  dataset.target = Eigen::ArrayXd::Zero(row_count);
  pbrfit::RandomStream random(7, 0);
  for (Eigen::Index c = 0; c < dataset.inputs.cols(); ++c) {
    for (Eigen::Index r = 0; r < dataset.inputs.rows(); ++r) dataset.inputs(r, c) = 2.0 * random.uniform() - 1.0;
  }
  return dataset;
}

double node_rows(const std::vector<Expression>& expressions, std::size_t count) {
  double nodes = 0.0;
  for (std::size_t e = 0; e < count; ++e) nodes += static_cast<double>(expressions[e].nodes);
  return nodes * row_count;
}

template <class F>
double best_seconds(int repeats, F pass) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    pass();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

volatile double sink = 0.0;  // keeps the outputs observable

template <class T>
double batch_rate(const std::vector<Expression>& expressions, const Dataset& dataset, int repeats) {
  BatchInterpreter<T> interpreter(dataset);
  std::vector<T> out(row_count);
  const double seconds = best_seconds(repeats, [&] {
    for (const Expression& expression : expressions) {
      interpreter.evaluate(expression.program, out);
      sink = sink + static_cast<double>(out[0]);
    }
  });
  return node_rows(expressions, expressions.size()) / seconds;
}

template <class T>
double walker_rate(const std::vector<Expression>& expressions, std::size_t count, const Dataset& dataset, int repeats) {
  std::vector<T> rows(row_count * input_count);
  for (std::size_t r = 0; r < row_count; ++r) {
    for (std::size_t c = 0; c < input_count; ++c) rows[r * input_count + c] = static_cast<T>(dataset.inputs(r, c));
  }
  const double seconds = best_seconds(repeats, [&] {
    for (std::size_t e = 0; e < count; ++e) {
      T sum = 0;
      for (std::size_t r = 0; r < row_count; ++r) {
        sum += walk_tree<T>(expressions[e].program, std::span<const T>(rows.data() + r * input_count, input_count));
      }
      sink = sink + static_cast<double>(sum);
    }
  });
  return node_rows(expressions, count) / seconds;
}

const std::vector<pbrfit::KernelSet> kernel_sets = pbrfit::kernel_sets_available();

// One row per type: the batch interpreter in every kernel set this machine has, then the tree walker.
template <class T>
void report_row(const char* operators, const char* type, const std::vector<Expression>& expressions,
                std::size_t walker_count, const Dataset& dataset, int repeats) {
  std::printf("| %-14s | %s |", operators, type);
  double best = 0.0;
  for (auto set : kernel_sets) {
    pbrfit::use_kernel_set(set);
    const double rate = batch_rate<T>(expressions, dataset, repeats);
    best = std::max(best, rate);
    std::printf(" %9.3g |", rate);
  }
  pbrfit::use_kernel_set(pbrfit::best_kernel_set());
  const double walker = walker_rate<T>(expressions, walker_count, dataset, repeats);
  std::printf(" %9.3g | %6.1fx |\n", walker, best / walker);
}

void report(const char* operators, const std::vector<Expression>& expressions, std::size_t walker_count,
            const Dataset& dataset, int repeats) {
  report_row<float>(operators, "float32", expressions, walker_count, dataset, repeats);
  report_row<double>(operators, "float64", expressions, walker_count, dataset, repeats);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t count = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 1000;
  const std::size_t walker_count = std::min<std::size_t>(count, argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 200);
  const int repeats = argc > 3 ? std::atoi(argv[3]) : 3;
  const Dataset dataset = random_dataset();
  const std::vector<Opcode> arithmetic{Opcode::add, Opcode::sub, Opcode::mul, Opcode::div};
  const std::vector<Opcode> transcendental{Opcode::add, Opcode::sub, Opcode::mul, Opcode::div, Opcode::exp,
                                           Opcode::log, Opcode::sin, Opcode::cos, Opcode::sqrt};
  const std::vector<Opcode> trigonometric{Opcode::add, Opcode::sub, Opcode::mul, Opcode::div,
                                          Opcode::tan,  Opcode::asin, Opcode::acos, Opcode::atan};
  const auto arithmetic_set = random_expressions(count, arithmetic, 1);
  const auto transcendental_set = random_expressions(count, transcendental, 2);
  const auto trigonometric_set = random_expressions(count, trigonometric, 3);
  std::printf("%zu expressions of 1..%zu nodes (mean %.1f), %zu rows, block %zu rows; walker on %zu expressions\n",
              count, max_nodes, node_rows(arithmetic_set, count) / row_count / static_cast<double>(count), row_count,
              block_rows, walker_count);
  std::printf("| operators      | type    |");
  for (auto set : kernel_sets) std::printf(" batch, %s |", std::string(pbrfit::kernel_set_name(set)).c_str());
  std::printf(" tree walker | best batch / walker |\n|---|---|");
  for (std::size_t i = 0; i < kernel_sets.size(); ++i) std::printf("---|");
  std::printf("---|---|\n");
  const std::string operators = argc > 4 ? argv[4] : "all";
  const bool all = operators == "all";
  if (all || operators == "arithmetic") report("arithmetic", arithmetic_set, walker_count, dataset, repeats);
  if (all || operators == "transcendental") report("transcendental", transcendental_set, walker_count, dataset, repeats);
  if (all || operators == "trigonometric") report("trigonometric", trigonometric_set, walker_count, dataset, repeats);
  return 0;
}
