#include "pbrfit/jobs/symreg/symreg_workload.hpp"

#include <algorithm>
#include <stdexcept>

#include "pbrfit/gp/evolve.hpp"
#include "pbrfit/gp/program_bytes.hpp"

namespace pbrfit::jobs::symreg {

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
  add_stage(runtime::stage<Nothing, EpochInput, EpochResult>("epochs", std::uint32_t(settings_.epochs()), this)
                .items(&SymregWorkload::island_count)
                .input(&SymregWorkload::epoch_input)
                .compute(&SymregWorkload::evolve_island)
                .check(&SymregWorkload::check_epoch)
                .blocks(&SymregWorkload::epoch_blocks)
                .kept_through(&SymregWorkload::epoch_kept_through)
                .fold(&SymregWorkload::fold_epoch));
  add_stage(runtime::stage<Nothing, IslandFronts, FrontBlocks>("fronts", 1, this)
                .items(&SymregWorkload::one)
                .input(&SymregWorkload::island_fronts)
                .compute(&SymregWorkload::final_fronts)
                .blocks(&SymregWorkload::front_blocks));
}

bool SymregWorkload::output_solved(std::uint32_t stage, std::size_t output, const runtime::KeptResults& kept) const {
  for (std::uint64_t i = output * settings_.islands; i < (output + 1) * settings_.islands; ++i)
    if (kept.at<EpochResult>({stage, i}).state.reached_target) return true;
  return false;
}

EpochInput SymregWorkload::epoch_input(std::uint32_t step, std::uint64_t item, const runtime::KeptResults& kept) const {
  EpochInput input;
  input.migrants = gp::individuals_to_bytes({});
  if (step == 0) return input;
  const std::size_t output = output_of(item), islands = settings_.islands;
  const std::uint64_t first = output * islands, island = item - first;
  const std::uint64_t before = first + (island + islands - 1) % islands;  // the ring's previous island
  input.state = kept.at<EpochResult>({step - 1, item}).state;
  if (islands > 1) input.migrants = kept.at<EpochResult>({step - 1, before}).emigrants;
  input.solved = output_solved(step - 1, output, kept);
  return input;
}

EpochResult SymregWorkload::evolve_island(const runtime::StageTask<Nothing, EpochInput>& task) const {
  const std::size_t output = output_of(task.item());
  const auto& opts = options(output);
  const std::size_t inputs = input_count(output);
  IslandState state;
  if (task.input.state) state = decode_state(*task.input.state, inputs);
  else state.population = gp::random_population(opts, task.random(0));
  EpochResult epoch;
  if (task.input.solved || state.reached_target) {  // solved: the island keeps its state
    epoch.emigrants = gp::individuals_to_bytes(gp::pick_emigrants(state.population, settings_.migrants, opts));
    epoch.generation = state.population.generation;
    epoch.state = encode_state(state);
    return epoch;
  }
  const std::size_t done = task.step() * settings_.migration_interval;
  const std::size_t generations = std::min(settings_.migration_interval, settings_.generations - done);
  const auto migrants = gp::individuals_from_bytes(task.input.migrants, inputs);
  gp::EvolveResult evolved = gp::evolve(state.population, migrants, generations, opts,
                                        settings_.data->outputs[output].train, task.random(1));
  gp::ParetoArchive front(opts.objective_count());
  front.insert_all(state.front);
  std::vector<gp::ArchiveEntry> additions;
  for (const auto& entry : evolved.archive_additions)
    if (front.insert(entry)) additions.push_back(entry);
  const IslandState after{std::move(evolved.population), front.entries(),
                          state.reached_target || evolved.stats.reached_target};
  epoch.emigrants = gp::individuals_to_bytes(gp::pick_emigrants(after.population, settings_.migrants, opts));
  epoch.generation = after.population.generation;
  epoch.state = encode_state(after);
  epoch.additions = gp::archive_to_bytes(additions);
  epoch.evaluations = evolved.stats.evaluations;
  epoch.best_error = evolved.stats.best_error;
  return epoch;
}

void SymregWorkload::check_epoch(const StageItem& at, const EpochResult& epoch) const {
  epoch_record(epoch, input_count(output_of(at.item())));  // throws for programs that are not the output's
}

std::uint32_t SymregWorkload::next_stage(std::uint32_t completed, const ItemResults& results) const {
  const std::uint32_t fronts = first_stage("fronts");
  if (completed + 1 >= fronts) return completed + 1;
  const runtime::KeptResults kept(results);
  for (std::size_t o = 0; o < settings_.data->outputs.size(); ++o)
    if (!output_solved(completed, o, kept)) return completed + 1;
  return fronts;
}

}  // namespace pbrfit::jobs::symreg
