#include "pbrfit/gp/evolve.hpp"

#include <algorithm>
#include <numeric>

#include "island_run.hpp"
#include "pbrfit/gp/variation.hpp"

namespace pbrfit::gp {

EvolveResult evolve(const Population& island, std::span<const Individual> migrants, std::size_t generations,
                    const EvolveOptions& options, const Dataset& dataset, const RandomStream& random) {
  detail::IslandRun run(options, dataset, random, island.generation, island.stalled);
  run.admit(island.members, migrants);
  std::size_t completed = 0;
  while (completed < generations && !run.reached_target()) {
    const bool within_budget = run.step();
    ++completed;
    if (!within_budget) break;
  }
  return run.finish(completed);
}

Population random_population(const EvolveOptions& options, const RandomStream& random) {
  validate(options.shape);
  Population population;
  population.members.resize(options.population_size);
  for (std::size_t i = 0; i < options.population_size; ++i) {
    RandomStream slot = random.derive(i);
    population.members[i].program = random_program(options.shape, slot);
  }
  return population;
}

std::vector<Individual> pick_emigrants(const Population& population, std::size_t count, const EvolveOptions& options) {
  std::vector<Fitness> fitnesses;
  for (const Individual& member : population.members) fitnesses.push_back(member.fitness);
  std::vector<std::size_t> order(fitnesses.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (options.selection == SelectionScheme::pareto) {
    const ParetoRanking ranking = rank_by_pareto(fitnesses, options.objective_count());
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if (ranking.rank[a] != ranking.rank[b]) return ranking.rank[a] < ranking.rank[b];
      return parsimony_better(fitnesses[a], fitnesses[b], 0.0);
    });
  } else {
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return parsimony_better(fitnesses[a], fitnesses[b], options.tie_tolerance);
    });
  }
  std::vector<Individual> emigrants;
  for (std::size_t k = 0; k < std::min(count, order.size()); ++k) emigrants.push_back(population.members[order[k]]);
  return emigrants;
}

}  // namespace pbrfit::gp
