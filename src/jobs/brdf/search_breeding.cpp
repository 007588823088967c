// Breeding an island of the genBRDF search (brdf_search_workload.hpp): ring migration, statistics of the
// generation bred from, and the next genomes with their trees.
#include <algorithm>
#include <cmath>

#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "search_records.hpp"

namespace pbrfit::jobs::brdf {
namespace {

using Evaluated = BrdfSearchWorkload::Evaluated;

void write_members(ByteWriter& out, const std::vector<Evaluated>& members) {
  out.put_varint(members.size());
  for (const auto& m : members) {
    write_genome(out, m.genome);
    out.put(m.error);
    out.put(m.size);
    out.put(std::uint8_t(m.abandoned));
  }
}

std::vector<Evaluated> read_members(ByteReader& in) {
  std::vector<Evaluated> members(in.get_varint());
  for (auto& m : members) {
    m.genome = read_genome(in);
    m.error = in.get<double>();
    m.size = in.get<double>();
    m.abandoned = in.get<std::uint8_t>() != 0;
  }
  return members;
}

// Better first: lower error, then smaller tree, then earlier slot.
std::vector<std::size_t> ranked(const std::vector<Evaluated>& members) {
  std::vector<std::size_t> order(members.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (members[a].error != members[b].error) return members[a].error < members[b].error;
    return members[a].size < members[b].size;
  });
  return order;
}

void record_statistics(const std::vector<Evaluated>& members, BreedRecord& record) {
  std::vector<double> errors, sizes;
  std::vector<std::uint8_t> abandoned;
  for (const auto& m : members) errors.push_back(m.error), sizes.push_back(m.size), abandoned.push_back(m.abandoned);
  record.statistics = island_statistics(errors, sizes, abandoned);
}

}  // namespace

Bytes BrdfSearchWorkload::breeding_input(std::uint32_t stage, std::uint64_t island, const ItemResults& kept) const {
  ByteWriter out;
  const std::uint32_t g = generation_of(stage);
  if (g == 0) return out.take();
  const auto all = generation_members(stage, kept);
  const std::size_t p = settings_.population;
  std::vector<Evaluated> own(all.begin() + std::ptrdiff_t(island * p), all.begin() + std::ptrdiff_t((island + 1) * p));
  std::vector<Evaluated> migrants;
  if (settings_.islands > 1 && g % settings_.migration_interval == 0) {
    const std::size_t before = (island + settings_.islands - 1) % settings_.islands;
    const std::vector<Evaluated> theirs(all.begin() + std::ptrdiff_t(before * p), all.begin() + std::ptrdiff_t((before + 1) * p));
    const auto order = ranked(theirs);
    for (std::size_t k = 0; k < settings_.migrants; ++k) migrants.push_back(theirs[order[k]]);
  }
  write_members(out, own);
  write_members(out, migrants);
  return out.take();
}

BreedRecord& BrdfSearchWorkload::with_trees(BreedRecord& record) const {
  for (const auto& genome : record.genomes) record.trees.push_back(gp::reify(settings_.seed, genome, settings_.grammar));
  return record;
}

Bytes BrdfSearchWorkload::breed(const runtime::ItemTask& task) const {
  BreedRecord record;
  record.generation = generation_of(task.id.stage);
  if (task.input.empty()) {
    record.genomes = gp::initial_genomes(settings_.population, task.random(0));
    return encode(with_trees(record));
  }
  ByteReader in(task.input);
  std::vector<Evaluated> own = read_members(in);
  const std::vector<Evaluated> migrants = read_members(in);
  record.generation -= 1;  // the statistics are those of the generation bred from
  record_statistics(own, record);
  const auto order = ranked(own);
  for (std::size_t k = 0; k < migrants.size(); ++k) own[order[own.size() - 1 - k]] = migrants[k];  // the worst go
  record.migrants_in = std::uint32_t(migrants.size());
  std::vector<gp::EditIndividual> population;
  for (const auto& m : own) population.push_back({m.genome, {m.error, m.size, 0.0, true}});
  record.genomes = gp::breed_island(population, settings_.evolution, task.random(0));
  return encode(with_trees(record));
}

}  // namespace pbrfit::jobs::brdf
