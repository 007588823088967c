// The schema of a `symreg` job's section (docs/job-files.md, kind `symreg`).
#include <limits>

#include "pbrfit/gp/opcode.hpp"
#include "pbrfit/jobs/symreg/symreg_kind.hpp"

namespace pbrfit::jobs::symreg {
namespace {

std::vector<std::string> operator_names() {
  std::vector<std::string> names;
  for (std::size_t k = 1; k < gp::opcode_count; ++k) names.emplace_back(gp::opcode_table[k].name);  // not identity
  return names;
}

spec::Schema cost_schema() {
  spec::Schema s("cost");
  s.choice("operator", operator_names(), "the operator").require();
  s.number("cost", "its cost in the shader-cost objective").range(0.0, 1e6).require();
  return s;
}

spec::Schema anchor_schema() {
  spec::Schema s("anchor");
  s.string("name", "what the reference is, e.g. narkowicz-2014").require();
  s.string("output", "the output it approximates (default: the only one)");
  s.string("expression", "the reference formula, an expression of the output's inputs").require();
  return s;
}

}  // namespace

spec::Schema symreg_schema() {
  using std::int64_t;
  spec::Schema s("symreg");
  s.section("dataset", dataset_schema(), "the data: a generator, a CSV file or tables of a pbrfit result").require();
  s.string_list("operators", 1, gp::opcode_count, "the operators programs may use", operator_names())
      .defaults_to(std::vector<std::string>{"add", "sub", "mul", "div"});
  s.number("constant_probability", "the chance a new leaf is a constant rather than an input").range(0, 1).defaults_to(0.2);
  s.number("constant_min", "random constants are uniform in [constant_min, constant_max]").defaults_to(-1.0);
  s.number("constant_max", "see constant_min").defaults_to(1.0);
  s.integer("max_length", "instructions per program, introns included").range(1, 64).defaults_to(int64_t{32});
  s.integer("islands", "islands per output, on a ring").range(1, 4096).defaults_to(int64_t{4});
  s.integer("population", "programs per island").range(2, 1'000'000).defaults_to(int64_t{500});
  s.integer("generations", "generations per island").range(1, 100'000'000).defaults_to(int64_t{100});
  s.integer("migration_interval", "generations between migrations (an epoch)").range(1, 1'000'000).defaults_to(int64_t{10});
  s.integer("migrants", "the best programs each island sends to the next every epoch").range(0, 1'000'000).defaults_to(int64_t{5});
  s.choice("selection", {"pareto", "tournament"}, "NSGA-II on error and cost, or tournaments with parsimony")
      .defaults_to(std::string("pareto"));
  s.integer("tournament_size", "contestants per parent tournament").range(1, 1000).defaults_to(int64_t{2});
  s.integer("elites", "tournament selection: best programs kept unchanged").range(0, 1'000'000).defaults_to(int64_t{1});
  s.number("crossover_rate", "the chance an offspring starts from two parents").range(0, 1).defaults_to(0.9);
  s.number("mutation_rate", "the chance a crossover child is also mutated").range(0, 1).defaults_to(0.5);
  s.choice("error", {"rmse", "max_abs", "relative"}, "the error objective").defaults_to(std::string("rmse"));
  s.choice("precision", {"float32", "float64"}, "the interpreter's arithmetic (errors accumulate in float64)")
      .defaults_to(std::string("float32"));
  s.boolean("piecewise_objective", "a third objective: the number of min, max, abs and saturate").defaults_to(false);
  s.number("piecewise_penalty", "cost added per piecewise operator").range(0, 1e6).defaults_to(0.0);
  s.section_list("costs", cost_schema(), 0, gp::opcode_count, "changes to the GCN-like cost table");
  s.integer("constant_fits_per_generation", "offspring whose constants Nelder-Mead fits each generation")
      .range(0, 1'000'000).defaults_to(int64_t{1});
  s.integer("constant_fit_evaluations", "evaluations per constant fit").range(1, 1'000'000).defaults_to(int64_t{300});
  s.integer("restart_after_stall", "generations without progress before an island restarts (0: never)")
      .range(0, 100'000'000).defaults_to(int64_t{10});
  s.number("target_error", "stop once an island's best error is at most this").at_least(0).defaults_to(0.0);
  s.integer("max_evaluations", "program evaluations over the whole run (0: only the generations limit)")
      .range(0, std::numeric_limits<int64_t>::max()).defaults_to(int64_t{0});
  s.section_list("anchors", anchor_schema(), 0, 64, "reference formulas measured beside the front");
  return s;
}

}  // namespace pbrfit::jobs::symreg
