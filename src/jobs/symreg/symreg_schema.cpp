// The keys of a `symreg` job's section (docs/job-files.md, kind `symreg`), each bound to what it fills, and
// the checks that span keys, in the order a job is refused by them.
#include <algorithm>
#include <limits>
#include <stdexcept>

#include "pbrfit/gp/error_measure.hpp"
#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/opcode.hpp"
#include "pbrfit/jobs/symreg/symreg_kind.hpp"

namespace pbrfit::jobs::symreg {
namespace {

std::vector<std::string> operator_names() {
  std::vector<std::string> names;
  for (std::size_t k = 1; k < gp::opcode_count; ++k) names.emplace_back(gp::opcode_table[k].name);  // not identity
  return names;
}

gp::Opcode opcode_of(const std::string& name) {
  const auto op = gp::opcode_named(name);
  if (!op) throw std::logic_error("symreg: the schema let an unknown operator through: " + name);
  return *op;
}

struct CostEntry {
  std::string op;
  double cost = 0.0;
};

struct AnchorEntry {
  spec::Located<std::string> name, output, expression;
};

// The section: the settings it fills, and what the checks turn into settings once the data is known.
struct SymregSection {
  SymregSettings settings;
  DatasetSection dataset;
  std::vector<AnchorEntry> anchors;
};

spec::Keys<CostEntry> cost_keys() {
  spec::Keys<CostEntry> k("cost");
  k.choice("operator", operator_names(), "the operator", &CostEntry::op).require();
  k.number("cost", "its cost in the shader-cost objective", &CostEntry::cost).range(0.0, 1e6).require();
  return k;
}

spec::Keys<AnchorEntry> anchor_keys() {
  spec::Keys<AnchorEntry> k("anchor");
  k.string("name", "what the reference is, e.g. narkowicz-2014", &AnchorEntry::name).require();
  k.string("output", "the output it approximates (default: the only one)", &AnchorEntry::output);
  k.string("expression", "the reference formula, an expression of the output's inputs", &AnchorEntry::expression)
      .require();
  return k;
}

Anchor anchor_of(const AnchorEntry& entry, const SymregData& data) {
  std::size_t output = 0;
  if (entry.output.written) {
    while (output < data.outputs.size() && data.outputs[output].name != entry.output.value) ++output;
    if (output == data.outputs.size()) entry.output.reject("is '" + entry.output.value + "', not an output of the data");
  } else if (data.outputs.size() > 1) {
    entry.name.reject("needs 'output' when the data has several outputs");
  }
  const auto parsed = gp::parse_expression(entry.expression.value, {data.outputs[output].inputs, {}});
  if (const auto* error = std::get_if<gp::ExpressionError>(&parsed))
    entry.expression.reject("has an error at line " + std::to_string(error->line) + ", column " +
                            std::to_string(error->column) + ": " + error->message);
  return {entry.name.value, output, entry.expression.value, std::get<gp::ParsedExpression>(parsed).program};
}

spec::Keys<SymregSection> make_symreg_keys() {
  using S = SymregSection;
  using std::int64_t;
  spec::Keys<S> k("symreg");
  k.section("dataset", dataset_keys(), "the data: a generator, a CSV file or tables of a pbrfit result", &S::dataset)
      .require();
  k.string_list("operators", 1, gp::opcode_count, "the operators programs may use",
                [](S& s, const std::vector<std::string>& names) {
                  auto& operators = s.settings.evolve.shape.operators;
                  operators = {};
                  for (const auto& name : names) operators.insert(opcode_of(name));
                },
                operator_names())
      .defaults_to(std::vector<std::string>{"add", "sub", "mul", "div"});
  k.number("constant_probability", "the chance a new leaf is a constant rather than an input",
           [](S& s, double p) { s.settings.evolve.shape.constant_probability = p; })
      .range(0, 1)
      .defaults_to(0.2);
  k.number("constant_min", "random constants are uniform in [constant_min, constant_max]",
           [](S& s, double v) { s.settings.evolve.shape.constant_min = v; })
      .defaults_to(-1.0);
  k.number("constant_max", "see constant_min", [](S& s, double v) { s.settings.evolve.shape.constant_max = v; })
      .defaults_to(1.0);
  k.integer("max_length", "instructions per program, introns included",
            [](S& s, int64_t n) {
              auto& shape = s.settings.evolve.shape;
              shape.max_length = std::size_t(n);
              shape.initial_max_length = std::min<std::size_t>(shape.initial_max_length, shape.max_length);
            })
      .range(1, 64)
      .defaults_to(int64_t{32});
  k.integer("islands", "islands per output, on a ring", [](S& s, int64_t n) { s.settings.islands = std::size_t(n); })
      .range(1, 4096)
      .defaults_to(int64_t{4});
  k.integer("population", "programs per island",
            [](S& s, int64_t n) { s.settings.evolve.population_size = std::size_t(n); })
      .range(2, 1'000'000)
      .defaults_to(int64_t{500});
  k.integer("generations", "generations per island", [](S& s, int64_t n) { s.settings.generations = std::size_t(n); })
      .range(1, 100'000'000)
      .defaults_to(int64_t{100});
  k.integer("migration_interval", "generations between migrations (an epoch)",
            [](S& s, int64_t n) { s.settings.migration_interval = std::size_t(n); })
      .range(1, 1'000'000)
      .defaults_to(int64_t{10});
  k.integer("migrants", "the best programs each island sends to the next every epoch",
            [](S& s, int64_t n) { s.settings.migrants = std::size_t(n); })
      .range(0, 1'000'000)
      .defaults_to(int64_t{5});
  k.choice<gp::SelectionScheme>("selection",
                                {{"pareto", gp::SelectionScheme::pareto},
                                 {"tournament", gp::SelectionScheme::tournament}},
                                "NSGA-II on error and cost, or tournaments with parsimony",
                                [](S& s, gp::SelectionScheme scheme) { s.settings.evolve.selection = scheme; })
      .defaults_to(std::string("pareto"));
  k.integer("tournament_size", "contestants per parent tournament",
            [](S& s, int64_t n) { s.settings.evolve.tournament_size = std::size_t(n); })
      .range(1, 1000)
      .defaults_to(int64_t{2});
  k.integer("elites", "tournament selection: best programs kept unchanged",
            [](S& s, int64_t n) { s.settings.evolve.elites = std::size_t(n); })
      .range(0, 1'000'000)
      .defaults_to(int64_t{1});
  k.number("crossover_rate", "the chance an offspring starts from two parents",
           [](S& s, double p) { s.settings.evolve.crossover_rate = p; })
      .range(0, 1)
      .defaults_to(0.9);
  k.number("mutation_rate", "the chance a crossover child is also mutated",
           [](S& s, double p) { s.settings.evolve.mutation_rate = p; })
      .range(0, 1)
      .defaults_to(0.5);
  k.choice("error", {"rmse", "max_abs", "relative"}, "the error objective",
           [](S& s, const std::string& name) { s.settings.evolve.fitness.error.measure = *gp::error_measure_named(name); })
      .defaults_to(std::string("rmse"));
  k.choice<gp::Precision>("precision", {{"float32", gp::Precision::float32}, {"float64", gp::Precision::float64}},
                          "the interpreter's arithmetic (errors accumulate in float64)",
                          [](S& s, gp::Precision p) { s.settings.evolve.fitness.precision = p; })
      .defaults_to(std::string("float32"));
  k.boolean("piecewise_objective", "a third objective: the number of min, max, abs and saturate",
            [](S& s, bool on) { s.settings.evolve.piecewise_objective = on; })
      .defaults_to(false);
  k.number("piecewise_penalty", "cost added per piecewise operator",
           [](S& s, double v) { s.settings.evolve.fitness.costs.piecewise_penalty = v; })
      .range(0, 1e6)
      .defaults_to(0.0);
  k.section_list("costs", cost_keys(), 0, gp::opcode_count, "changes to the GCN-like cost table",
                 [](S& s, const std::vector<CostEntry>& costs) {
                   for (const auto& c : costs) s.settings.evolve.fitness.costs[opcode_of(c.op)] = c.cost;
                 });
  k.integer("constant_fits_per_generation", "offspring whose constants Nelder-Mead fits each generation",
            [](S& s, int64_t n) { s.settings.evolve.constant_fits_per_generation = std::size_t(n); })
      .range(0, 1'000'000)
      .defaults_to(int64_t{1});
  k.integer("constant_fit_evaluations", "evaluations per constant fit",
            [](S& s, int64_t n) { s.settings.evolve.constants.max_evaluations = std::size_t(n); })
      .range(1, 1'000'000)
      .defaults_to(int64_t{300});
  k.integer("restart_after_stall", "generations without progress before an island restarts (0: never)",
            [](S& s, int64_t n) { s.settings.evolve.restart_after_stall = std::size_t(n); })
      .range(0, 100'000'000)
      .defaults_to(int64_t{10});
  k.number("target_error", "stop once an island's best error is at most this",
           [](S& s, double v) { s.settings.evolve.target_error = v; })
      .at_least(0)
      .defaults_to(0.0);
  k.integer("max_evaluations", "program evaluations over the whole run (0: only the generations limit)",
            [](S& s, int64_t n) { s.settings.max_evaluations = std::size_t(n); })
      .range(0, std::numeric_limits<int64_t>::max())
      .defaults_to(int64_t{0});
  k.section_list("anchors", anchor_keys(), 0, 64, "reference formulas measured beside the front", &S::anchors);

  k.check("constant_max", [](S& s) -> std::string {
    const auto& shape = s.settings.evolve.shape;
    return shape.constant_min > shape.constant_max ? "must be at least 'constant_min'" : "";
  });
  k.check("elites", [](S& s) -> std::string {
    return s.settings.evolve.elites >= s.settings.evolve.population_size ? "must be smaller than 'population'" : "";
  });
  k.check("migrants", [](S& s) -> std::string {
    return s.settings.migrants >= s.settings.evolve.population_size ? "must be smaller than 'population'" : "";
  });
  k.check("dataset", [](S& s, const SourcePosition& where) {
    s.settings.data = load_symreg_data(s.dataset, where);
    return std::string();
  });
  k.check("anchors", [](S& s) {
    for (const auto& entry : s.anchors) s.settings.anchors.push_back(anchor_of(entry, *s.settings.data));
    return std::string();
  });
  k.check("operators", [](S& s) -> std::string {
    try {
      gp::validate(s.settings.evolve);
    } catch (const std::invalid_argument& e) {
      return std::string("give an invalid search: ") + e.what();
    }
    return "";
  });
  return k;
}

const spec::Keys<SymregSection>& symreg_keys() {
  static const spec::Keys<SymregSection> keys = make_symreg_keys();
  return keys;
}

}  // namespace

const spec::Schema& symreg_schema() { return symreg_keys().schema(); }

SymregSettings symreg_settings(const spec::Section& symreg) { return symreg_keys().read(symreg).settings; }

}  // namespace pbrfit::jobs::symreg
