// The last stage of a symbolic-regression job (symreg_workload.hpp): every island's front merged into one
// Pareto front per output, measured, beside the anchors, with the knee's predictions and the
// sub-expressions that recur across the fronts. Its result is the blocks themselves.
#include <algorithm>
#include <map>
#include <set>

#include "pbrfit/gp/cost_model.hpp"
#include "pbrfit/gp/pareto.hpp"
#include "pbrfit/gp/live_code.hpp"
#include "pbrfit/gp/program_bytes.hpp"
#include "pbrfit/jobs/symreg/front_measures.hpp"
#include "pbrfit/jobs/symreg/symreg_workload.hpp"

namespace pbrfit::jobs::symreg {
namespace {

constexpr std::size_t recurring_limit = 50;

gp::ExpressionNames names_of(const SymregOutput& output) { return {output.inputs, {}}; }

store::Block rows_block(const std::string& group, const char* table, std::size_t rows) {
  return {group, table, {0}, {rows}, {}, {}};
}

store::Block front_block(const SymregOutput& output, const std::vector<gp::ArchiveEntry>& front, std::size_t knee,
                         const gp::CostTable& costs) {
  auto block = rows_block(output.name, "front", front.size());
  for (std::size_t k = 0; k < front.size(); ++k) {
    const auto& entry = front[k];
    const auto m = measure_program(entry.program, output.train, output.test);
    block.values.insert(block.values.end(), {gp::program_cost(entry.program, costs), m.operations,
                                             gp::piecewise_count(entry.program), m.rmse, m.max_abs_error,
                                             m.test_rmse, entry.generation, k == knee ? 1u : 0u});
    block.texts.push_back(expression_text(entry.program, names_of(output)));
    block.texts.push_back(constants_text(entry.program));
  }
  return block;
}

store::Block anchor_block(const SymregOutput& output, std::size_t index, const std::vector<Anchor>& anchors,
                          const gp::CostTable& costs) {
  auto block = rows_block(output.name, "anchors", 0);
  for (const auto& anchor : anchors) {
    if (anchor.output != index) continue;
    const auto m = measure_program(anchor.program, output.train, output.test);
    block.values.insert(block.values.end(), {gp::program_cost(anchor.program, costs), m.operations, m.rmse,
                                             m.max_abs_error});
    block.texts.insert(block.texts.end(), {anchor.name, anchor.text});
    ++block.count[0];
  }
  return block;
}

store::Block prediction_block(const SymregOutput& output, const gp::Program& program) {
  const auto predicted = predictions(program, output.train);
  auto block = rows_block(output.name, "knee_prediction", predicted.size());
  for (std::size_t r = 0; r < predicted.size(); ++r) {
    for (Eigen::Index k = 0; k < output.train.inputs.cols(); ++k) block.values.push_back(output.train.inputs(Eigen::Index(r), k));
    block.values.push_back(output.train.target[Eigen::Index(r)]);
    block.values.push_back(predicted[r]);
  }
  return block;
}

// The sub-expressions of two or more operations in a program's live code, as texts.
std::set<std::string> subexpressions(const gp::Program& program, const gp::ExpressionNames& names) {
  std::set<std::string> out;
  const auto live = gp::live_instructions(program);
  for (std::size_t i = 0; i < program.length; ++i) {
    if (!live.test(i) || program.code[i].op == gp::Opcode::identity) continue;
    gp::Program sub = program;
    sub.length = std::uint16_t(i + 1);
    sub = gp::without_introns(sub);
    if (gp::live_length(sub) >= 2) out.insert(expression_text(sub, names));
  }
  return out;
}

store::Block recurring_block(const std::vector<std::vector<gp::ArchiveEntry>>& fronts, const SymregData& data) {
  std::map<std::string, std::pair<std::uint32_t, std::set<std::string>>> seen;
  for (std::size_t o = 0; o < fronts.size(); ++o)
    for (const auto& entry : fronts[o])
      for (const auto& text : subexpressions(entry.program, names_of(data.outputs[o]))) {
        ++seen[text].first;
        seen[text].second.insert(data.outputs[o].name);
      }
  std::vector<std::pair<std::string, std::pair<std::uint32_t, std::set<std::string>>>> recurring;
  for (auto& item : seen)
    if (item.second.first >= 2) recurring.push_back(item);
  std::stable_sort(recurring.begin(), recurring.end(),
                   [](const auto& a, const auto& b) { return a.second.first > b.second.first; });
  if (recurring.size() > recurring_limit) recurring.resize(recurring_limit);
  auto block = rows_block("subexpressions", "recurring", recurring.size());
  for (const auto& [text, found] : recurring) {
    std::string outputs;
    for (const auto& name : found.second) outputs += (outputs.empty() ? "" : ", ") + name;
    block.values.push_back(found.first);
    block.texts.insert(block.texts.end(), {text, outputs});
  }
  return block;
}

}  // namespace

// The fronts of the last epoch run (later ones are skipped once every output is solved).
SymregWorkload::IslandFronts SymregWorkload::island_fronts(std::uint32_t, std::uint64_t,
                                                           const runtime::KeptResults& kept) const {
  if (kept.bytes().empty()) throw std::logic_error("symreg: no island epochs were kept for the fronts");
  const std::uint32_t last = kept.bytes().rbegin()->first.stage;
  IslandFronts fronts;
  for (std::uint64_t i = 0; i < island_count(0); ++i) fronts.push_back(kept.at<EpochResult>({last, i}).state.front);
  return fronts;
}

SymregWorkload::FrontBlocks SymregWorkload::final_fronts(const runtime::StageTask<Nothing, IslandFronts>& task) const {
  const auto& data = *settings_.data;
  if (task.input.size() != island_count(0)) throw RunError("symreg: the fronts stage lacks islands");
  std::vector<gp::ParetoArchive> merged;
  for (std::size_t o = 0; o < data.outputs.size(); ++o) merged.emplace_back(options(o).objective_count());
  for (std::uint64_t i = 0; i < island_count(0); ++i)
    merged[output_of(i)].insert_all(gp::archive_from_bytes(task.input[i], input_count(output_of(i))));
  std::vector<std::vector<gp::ArchiveEntry>> fronts;
  std::vector<store::Block> blocks;
  for (std::size_t o = 0; o < data.outputs.size(); ++o) {
    fronts.push_back(merged[o].entries());
    const auto& costs = options(o).fitness.costs;
    const std::size_t knee = fronts.back().empty() ? 0 : gp::knee_index(fronts.back());
    blocks.push_back(front_block(data.outputs[o], fronts.back(), knee, costs));
    blocks.push_back(anchor_block(data.outputs[o], o, settings_.anchors, costs));
    if (!fronts.back().empty()) blocks.push_back(prediction_block(data.outputs[o], fronts.back()[knee].program));
  }
  blocks.push_back(recurring_block(fronts, data));
  std::erase_if(blocks, [](const store::Block& b) { return b.count[0] == 0; });
  ByteWriter out;
  out.put_varint(blocks.size());
  for (const auto& block : blocks) codec_.encode(out, block);
  return out.take();
}

}  // namespace pbrfit::jobs::symreg
