#include "pbrfit/gp/edit_evolution.hpp"

#include <stdexcept>

namespace pbrfit::gp {
namespace {

bool better(const EditIndividual& a, const EditIndividual& b) {
  if (a.fitness.error != b.fitness.error) return a.fitness.error < b.fitness.error;
  return a.fitness.cost < b.fitness.cost;
}

std::size_t tournament(std::span<const EditIndividual> population, std::size_t size, RandomStream& random) {
  std::size_t best = random.below(population.size());
  for (std::size_t k = 1; k < size; ++k) {
    const std::size_t contender = random.below(population.size());
    if (better(population[contender], population[best]) ||
        (!better(population[best], population[contender]) && contender < best))
      best = contender;
  }
  return best;
}

Genome crossed(const Genome& head, const Genome& tail, std::size_t head_cut, std::size_t tail_cut) {
  Genome out(head.begin(), head.begin() + std::ptrdiff_t(head_cut));
  out.insert(out.end(), tail.begin() + std::ptrdiff_t(tail_cut), tail.end());
  return out;
}

Genome mutated(Genome genome, const EditEvolutionOptions& options, RandomStream random) {
  if (genome.size() >= options.max_genome) genome.resize(options.max_genome - 1);
  genome.push_back(random_edit(random));
  return genome;
}

}  // namespace

std::vector<Genome> breed_island(std::span<const EditIndividual> population, const EditEvolutionOptions& options,
                                 const RandomStream& random) {
  const std::size_t n = population.size(), half = n / 2;
  if (n < 2 || n % 2 != 0) throw std::invalid_argument("edit evolution: a population needs an even size >= 2");
  RandomStream selection = random.derive(std::uint64_t(1) << 32);
  std::vector<std::size_t> parents(half);
  for (auto& p : parents) p = tournament(population, options.tournament_size, selection);
  std::vector<Genome> next(n);
  for (std::size_t k = 0; k < half; ++k) next[k] = mutated(population[parents[k]].genome, options, random.derive(k));
  for (std::size_t pair = 0; pair * 2 < half + (half % 2); ++pair) {
    const Genome& a = population[parents[(2 * pair) % half]].genome;
    const Genome& b = population[parents[(2 * pair + 1) % half]].genome;
    RandomStream cuts = random.derive(n + pair);
    const std::size_t cut_a = cuts.below(a.size() + 1), cut_b = cuts.below(b.size() + 1);
    const std::size_t slot = half + 2 * pair;
    next[slot] = mutated(crossed(a, b, cut_a, cut_b), options, random.derive(slot));
    if (slot + 1 < n) next[slot + 1] = mutated(crossed(b, a, cut_b, cut_a), options, random.derive(slot + 1));
  }
  return next;
}

std::vector<Genome> initial_genomes(std::size_t n, const RandomStream& random) {
  std::vector<Genome> genomes(n);
  for (std::size_t s = 0; s < n; ++s) {
    RandomStream slot = random.derive(s);
    genomes[s] = {random_edit(slot)};
  }
  return genomes;
}

}  // namespace pbrfit::gp
