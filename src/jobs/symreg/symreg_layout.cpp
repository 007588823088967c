// The result layout of a symbolic-regression job and the blocks of its epochs (symreg_workload.hpp).
#include <cmath>

#include "pbrfit/core/error.hpp"
#include "pbrfit/gp/cost_model.hpp"
#include "pbrfit/gp/error_measure.hpp"
#include "pbrfit/gp/operator_set.hpp"
#include "pbrfit/jobs/symreg/front_measures.hpp"
#include "pbrfit/jobs/symreg/symreg_workload.hpp"

namespace pbrfit::jobs::symreg {
namespace {

using store::ValueType;

store::Table records(const char* name, const char* label, const char* description, std::vector<store::Field> fields,
                     std::map<std::string, std::string> attributes = {}) {
  store::Table t{name, {label}, description, ValueType::f64, std::move(fields), true};
  t.attributes = std::move(attributes);
  return t;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string operator_names(const gp::OperatorSet& set) {
  std::vector<std::string> names;
  for (gp::Opcode op : set.members()) names.emplace_back(gp::name(op));
  return joined(names);
}

}  // namespace

store::Group SymregWorkload::output_group(std::size_t o) const {
  const SymregOutput& output = settings_.data->outputs[o];
  const gp::EvolveOptions& opts = options(o);
  store::Group g;
  g.name = output.name;
  g.description = "symbolic regression of " + output.name + " over " + joined(output.inputs) +
                  ": linear GP on " + std::to_string(settings_.islands) + " islands on a ring, Pareto front of " +
                  "error vs shader cost";
  g.attributes = {{"output", output.name},
                  {"inputs", joined(output.inputs)},
                  {"source", settings_.data->source},
                  {"rows", std::to_string(output.train.rows())},
                  {"test_rows", std::to_string(output.test.rows())},
                  {"operators", operator_names(opts.shape.operators)},
                  {"error_measure", std::string(gp::name(opts.fitness.error.measure))},
                  {"precision", opts.fitness.precision == gp::Precision::float32 ? "float32" : "float64"},
                  {"islands", std::to_string(settings_.islands)},
                  {"population", std::to_string(opts.population_size)},
                  {"generations", std::to_string(settings_.generations)},
                  {"migration", std::to_string(settings_.migrants) + " every " +
                                    std::to_string(settings_.migration_interval) + " generations"}};
  g.tables = {
      records("front", "member", "the Pareto front of error vs cost over all islands, by cost",
              {{"expression", ValueType::text, "the program as an expression (statements separated by '; ')"},
               {"constants", ValueType::text, "its live constants"},
               {"cost", ValueType::f64, "estimated shader cost (the run's cost table)"},
               {"operations", ValueType::u32, "live operations"},
               {"piecewise", ValueType::u32, "live min, max, abs and saturate"},
               {"rmse", ValueType::f64, "RMSE on the training rows, in double"},
               {"max_abs_error", ValueType::f64, "largest absolute error on the training rows"},
               {"test_rmse", ValueType::f64, "RMSE on the test rows: fresh points or held-out rows (NaN without them)"},
               {"generation", ValueType::u64, "the generation it was first evaluated in"},
               {"knee", ValueType::u8, "1 for the knee of the front (the default export)"}},
              {{"role", "front"}}),
      records("archive", "entry", "every program that entered an island's non-dominated set, in epoch and island order",
              {{"expression", ValueType::text, "the program"},
               {"cost", ValueType::f64, "estimated shader cost"},
               {"operations", ValueType::u32, "live operations"},
               {"error", ValueType::f64, "the search's error measure"},
               {"generation", ValueType::u64, "when it was first evaluated"},
               {"island", ValueType::u32, "its island"},
               {"epoch", ValueType::u32, "the migration epoch"}}),
      records("log", "row", "a row per island and epoch",
              {{"epoch", ValueType::u32, "migration epoch"},
               {"island", ValueType::u32, "island"},
               {"generation", ValueType::u64, "generations completed by the island"},
               {"evaluations", ValueType::u64, "program evaluations in the epoch"},
               {"best_error", ValueType::f64, "best error in the island's population"},
               {"front_size", ValueType::u32, "the island's non-dominated programs"}}),
      records("anchors", "anchor", "reference expressions from the job, measured like the front",
              {{"name", ValueType::text, "the anchor's name"},
               {"expression", ValueType::text, "its text"},
               {"cost", ValueType::f64, "estimated shader cost"},
               {"operations", ValueType::u32, "live operations"},
               {"rmse", ValueType::f64, "RMSE on the training rows"},
               {"max_abs_error", ValueType::f64, "largest absolute error on the training rows"}},
              {{"role", "anchors"}}),
  };
  std::vector<store::Field> prediction;
  for (const auto& input : output.inputs) prediction.push_back({input, ValueType::f64, "input"});
  prediction.push_back({"target", ValueType::f64, "the data"});
  prediction.push_back({"prediction", ValueType::f64, "the knee's output"});
  g.tables.push_back(records("knee_prediction", "row", "the knee member at every training row", prediction,
                             {{"role", "residuals"}}));
  return g;
}

store::ResultLayout SymregWorkload::layout() const {
  store::ResultLayout layout;
  for (std::size_t o = 0; o < settings_.data->outputs.size(); ++o) layout.groups.push_back(output_group(o));
  store::Group sub;
  sub.name = "subexpressions";
  sub.description = "sub-expressions (two or more operations) found in several front members, over all outputs";
  sub.tables = {records("recurring", "row", "by the number of front members that contain them",
                        {{"subexpression", ValueType::text, "its text"},
                         {"members", ValueType::u32, "front members containing it"},
                         {"outputs", ValueType::text, "the outputs whose fronts contain it"}})};
  layout.groups.push_back(sub);
  return layout;
}

std::vector<store::Block> SymregWorkload::epoch_blocks(const StageItem& at, const EpochResult& result) const {
  const WorkItemId id = at.id;
  const std::size_t o = output_of(id.item);
  const EpochRecord epoch = epoch_record(result, input_count(o));
  const SymregOutput& output = settings_.data->outputs[o];
  const std::uint64_t island = id.item - o * settings_.islands;
  store::Block log{output.name, "log", {0}, {1},
                   {id.stage, island, epoch.generation, epoch.evaluations, epoch.best_error, epoch.front.size()}};
  std::vector<store::Block> out = {log};
  if (epoch.additions.empty()) return out;
  store::Block archive{output.name, "archive", {0}, {epoch.additions.size()}};
  for (const auto& entry : epoch.additions) {
    archive.values.insert(archive.values.end(), {entry.fitness.cost, live_operations(entry.program), entry.fitness.error,
                                                 entry.generation, island, id.stage});
    archive.texts.push_back(expression_text(entry.program, {output.inputs, {}}));
  }
  out.push_back(std::move(archive));
  return out;
}

std::vector<store::Block> SymregWorkload::front_blocks(const StageItem&, const FrontBlocks& result) const {
  try {
    ByteReader in(result);
    const std::uint64_t count = in.get_varint();
    if (count > in.remaining()) throw ByteFormatError(in.offset(), "more blocks than bytes");
    std::vector<store::Block> out;
    for (std::uint64_t k = 0; k < count; ++k) out.push_back(codec_.decode(in));
    if (in.remaining() != 0) throw ByteFormatError(in.offset(), "trailing bytes");
    return out;
  } catch (const ByteFormatError& e) {
    throw RunError(std::string("a symbolic-regression front result is damaged: ") + e.what());
  }
}

}  // namespace pbrfit::jobs::symreg
