#include "pbrfit/jobs/symreg/symreg_workload.hpp"

#include <algorithm>
#include <stdexcept>

#include "pbrfit/gp/evolve.hpp"
#include "pbrfit/gp/program_bytes.hpp"

namespace pbrfit::jobs::symreg {
namespace {

const Bytes& kept_result(const ItemResults& kept, WorkItemId id) {
  const auto found = kept.find(id);
  if (found == kept.end()) throw std::logic_error("symreg: an island's previous epoch was not kept");
  return found->second;
}

}  // namespace

SymregWorkload::SymregWorkload(SymregSettings settings)
    : settings_(std::move(settings)), codec_(store::ResultLayout{}) {
  for (std::size_t o = 0; o < settings_.data->outputs.size(); ++o) {
    gp::EvolveOptions options = settings_.evolve;
    options.shape.input_count = input_count(o);
    if (settings_.max_evaluations > 0)
      options.max_evaluations = std::max<std::size_t>(
          settings_.max_evaluations / (settings_.epochs() * settings_.islands * settings_.data->outputs.size()), 1);
    options_.push_back(options);
  }
  codec_ = store::BlockCodec(layout());
}

std::uint64_t SymregWorkload::item_count(std::uint32_t stage) const {
  return is_final(stage) ? 1 : settings_.islands * settings_.data->outputs.size();
}

Bytes SymregWorkload::item_input(std::uint32_t stage, std::uint64_t item, const ItemResults& kept) const {
  if (is_final(stage)) {  // the last epoch run (later ones are skipped once every output is solved)
    if (kept.empty()) throw std::logic_error("symreg: no island epochs were kept for the fronts");
    const std::uint32_t last = kept.rbegin()->first.stage;
    ByteWriter out;
    for (std::uint64_t i = 0; i < item_count(last); ++i) out.put_bytes(kept_result(kept, {last, i}));
    return out.take();
  }
  if (stage == 0) return encode_input(EpochInput{});
  const std::size_t output = output_of(item), islands = settings_.islands;
  const std::uint64_t first = output * islands, island = item - first;
  const std::uint64_t before = first + (island + islands - 1) % islands;  // the ring's previous island
  bool solved = false;
  for (std::uint64_t i = first; i < first + islands; ++i)
    solved = solved || reached_target_of(kept_result(kept, {stage - 1, i}));
  EpochBytes neighbour = split_epoch(kept_result(kept, {stage - 1, before}));
  if (islands == 1) neighbour.emigrants = gp::individuals_to_bytes({});
  return next_input(split_epoch(kept_result(kept, {stage - 1, item})), neighbour, solved);
}

Bytes SymregWorkload::compute(const runtime::ItemTask& task) const {
  return is_final(task.id.stage) ? final_fronts(task) : evolve_island(task);
}

Bytes SymregWorkload::evolve_island(const runtime::ItemTask& task) const {
  const std::size_t output = output_of(task.id.item);
  const auto& opts = options(output);
  EpochInput input = decode_input(task.input, input_count(output));
  IslandEpoch epoch;
  if (!input.has_state) input.state.population = gp::random_population(opts, task.random(0));
  if (input.solved || input.state.reached_target) {  // solved: the island keeps its state
    epoch.state = std::move(input.state);
    epoch.emigrants = gp::pick_emigrants(epoch.state.population, settings_.migrants, opts);
    return encode_epoch(epoch);
  }
  const std::size_t done = task.id.stage * settings_.migration_interval;
  const std::size_t generations = std::min(settings_.migration_interval, settings_.generations - done);
  gp::EvolveResult evolved = gp::evolve(input.state.population, input.migrants, generations, opts,
                                        settings_.data->outputs[output].train, task.random(1));
  gp::ParetoArchive front(opts.objective_count());
  front.insert_all(input.state.front);
  for (const auto& entry : evolved.archive_additions)
    if (front.insert(entry)) epoch.additions.push_back(entry);
  epoch.state = {std::move(evolved.population), front.entries(),
                 input.state.reached_target || evolved.stats.reached_target};
  epoch.emigrants = gp::pick_emigrants(epoch.state.population, settings_.migrants, opts);
  epoch.evaluations = evolved.stats.evaluations;
  epoch.best_error = evolved.stats.best_error;
  return encode_epoch(epoch);
}

std::uint32_t SymregWorkload::next_stage(std::uint32_t completed, const ItemResults& kept) const {
  if (is_final(completed) || is_final(completed + 1)) return completed + 1;
  for (std::size_t o = 0; o < settings_.data->outputs.size(); ++o) {
    bool solved = false;
    for (std::uint64_t i = o * settings_.islands; i < (o + 1) * settings_.islands; ++i)
      solved = solved || reached_target_of(kept_result(kept, {completed, i}));
    if (!solved) return completed + 1;
  }
  return std::uint32_t(settings_.epochs());
}

std::uint32_t SymregWorkload::kept_through(WorkItemId id) const {
  return is_final(id.stage) ? id.stage : id.stage + 1;
}

}  // namespace pbrfit::jobs::symreg
