// Breeding an island of the genBRDF search (brdf_search_workload.hpp): ring migration, statistics of the
// generation bred from, and the next genomes with their trees.
#include <algorithm>
#include <cmath>

#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "search_records.hpp"

namespace pbrfit::jobs::brdf {
namespace {

// Better first: lower error, then smaller tree, then earlier slot.
std::vector<std::size_t> ranked(const std::vector<Parent>& members) {
  std::vector<std::size_t> order(members.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (members[a].error != members[b].error) return members[a].error < members[b].error;
    return members[a].size < members[b].size;
  });
  return order;
}

void record_statistics(const std::vector<Parent>& members, BreedRecord& record) {
  std::vector<double> errors, sizes;
  std::vector<std::uint8_t> abandoned;
  for (const auto& m : members) errors.push_back(m.error), sizes.push_back(m.size), abandoned.push_back(m.abandoned);
  record.statistics = island_statistics(errors, sizes, abandoned);
}

// Slots first .. first + count - 1 of a generation, as parents.
std::vector<Parent> parents(const std::vector<BrdfSearchWorkload::Evaluated>& all, std::size_t first, std::size_t count) {
  std::vector<Parent> out;
  for (std::size_t k = first; k < first + count; ++k) out.push_back({all[k].genome, all[k].error, all[k].size, all[k].abandoned});
  return out;
}

}  // namespace

BreedInput BrdfSearchWorkload::breeding_input(std::uint32_t generation, std::uint64_t island, const Kept& kept) const {
  BreedInput input;
  if (generation == 0) return input;
  const auto all = generation_members(generation - 1, kept);
  const std::size_t p = settings_.population;
  input.own = parents(all, island * p, p);
  if (settings_.islands > 1 && generation % settings_.migration_interval == 0) {
    const std::size_t before = (island + settings_.islands - 1) % settings_.islands;
    const auto theirs = parents(all, before * p, p);
    const auto order = ranked(theirs);
    for (std::size_t k = 0; k < settings_.migrants; ++k) input.migrants.push_back(theirs[order[k]]);
  }
  return input;
}

BreedRecord& BrdfSearchWorkload::with_trees(BreedRecord& record) const {
  for (const auto& genome : record.genomes) record.trees.push_back(gp::reify(settings_.seed, genome, settings_.grammar));
  return record;
}

BreedRecord BrdfSearchWorkload::breed(const Task<Nothing, BreedInput>& task) const {
  BreedRecord record;
  if (task.step() == 0) {
    record.genomes = gp::initial_genomes(settings_.population, task.random(0));
    return with_trees(record);
  }
  std::vector<Parent> own = task.input.own;
  const std::vector<Parent>& migrants = task.input.migrants;
  record.generation = task.step() - 1;  // the statistics are those of the generation bred from
  record_statistics(own, record);
  const auto order = ranked(own);
  for (std::size_t k = 0; k < migrants.size(); ++k) own[order[own.size() - 1 - k]] = migrants[k];  // the worst go
  record.migrants_in = std::uint32_t(migrants.size());
  std::vector<gp::EditIndividual> population;
  for (const auto& m : own) population.push_back({m.genome, {m.error, m.size, 0.0, true}});
  record.genomes = gp::breed_island(population, settings_.evolution, task.random(0));
  return with_trees(record);
}

void BrdfSearchWorkload::check_breed(const StageItem&, const BreedRecord& record) const {
  if (record.trees.size() != record.genomes.size())
    throw RunError("a BRDF search breeding record holds another number of trees than genomes");
}

}  // namespace pbrfit::jobs::brdf
