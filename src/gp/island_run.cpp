#include "island_run.hpp"

#include <algorithm>
#include <stdexcept>

#include "pbrfit/gp/constant_fitting.hpp"
#include "pbrfit/gp/variation.hpp"

namespace pbrfit::gp::detail {
namespace {

std::vector<Fitness> fitnesses_of(std::span<const Individual> individuals) {
  std::vector<Fitness> fitnesses;
  fitnesses.reserve(individuals.size());
  for (const Individual& individual : individuals) fitnesses.push_back(individual.fitness);
  return fitnesses;
}

// Better by more than a relative 1e-9 (any finite error improves on the worst).
bool improved(double best, double previous_best) {
  return best < previous_best && !(previous_best - best <= 1e-9 * previous_best);
}

}  // namespace

IslandRun::IslandRun(const EvolveOptions& options, const Dataset& dataset, const RandomStream& random,
                     std::uint64_t generation, std::uint64_t stalled)
    : options_(options),
      random_(random),
      evaluator_(dataset, options.fitness),
      archive_(options.objective_count()),
      generation_(generation),
      stalled_(stalled) {
  validate(options);
  if (options.shape.input_count != dataset.input_count()) {
    throw std::invalid_argument("the program shape's input count differs from the dataset's");
  }
}

bool IslandRun::evaluate(Individual& individual) {
  if (individual.fitness.evaluated) return true;
  if (evaluator_.evaluations() >= options_.max_evaluations) {
    budget_exhausted_ = true;
    return false;
  }
  individual.fitness = evaluator_(individual.program);
  individual.born = generation_;
  if (archive_.admits(individual.fitness)) archive_.insert({individual.program, individual.fitness, generation_});
  return true;
}

double IslandRun::best_error() const {
  double best = worst_error;
  for (const Individual& member : members_) best = std::min(best, member.fitness.error);
  return best;
}

void IslandRun::track_stall(double previous_best) {
  stalled_ = improved(best_error(), previous_best) ? 0 : stalled_ + 1;
}

void IslandRun::restart() {
  ++restarts_;
  stalled_ = 0;
  const RandomStream restart_stream = random_.derive(generation_);
  members_.resize(options_.population_size);
  for (std::size_t i = 0; i < members_.size(); ++i) {
    RandomStream random = restart_stream.derive((std::uint64_t{1} << 32) + i);
    members_[i] = {random_program(options_.shape, random), {}, 0};
    if (!evaluate(members_[i])) {
      members_.resize(i);
      break;
    }
  }
}

void IslandRun::admit(std::span<const Individual> members, std::span<const Individual> migrants) {
  std::vector<Individual> candidates;
  for (auto group : {members, migrants}) {
    for (const Individual& individual : group) {
      if (!is_valid(individual.program, options_.shape.input_count)) {
        throw std::invalid_argument("evolve: a program is not valid for the dataset's inputs");
      }
      candidates.push_back(individual);
      if (!evaluate(candidates.back())) candidates.pop_back();
    }
  }
  double members_best = worst_error;
  for (const Individual& member : members) members_best = std::min(members_best, member.fitness.error);
  members_ = survivors(candidates, {}, options_.population_size);
  if (improved(best_error(), members_best)) stalled_ = 0;
}

bool IslandRun::reached_target() const {
  return std::any_of(members_.begin(), members_.end(),
                     [&](const Individual& m) { return m.fitness.error <= options_.target_error; });
}

std::vector<Individual> IslandRun::survivors(std::span<const Individual> first, std::span<const Individual> second,
                                             std::size_t count) const {
  std::vector<Fitness> fitnesses = fitnesses_of(first);
  const std::vector<Fitness> more = fitnesses_of(second);
  fitnesses.insert(fitnesses.end(), more.begin(), more.end());
  count = std::min(count, fitnesses.size());
  std::vector<std::size_t> chosen;
  if (options_.selection == SelectionScheme::pareto) {
    chosen = select_survivors(fitnesses, count, options_.objective_count());
  } else {
    chosen.resize(fitnesses.size());
    for (std::size_t i = 0; i < chosen.size(); ++i) chosen[i] = i;
    std::stable_sort(chosen.begin(), chosen.end(), [&](std::size_t a, std::size_t b) {
      return parsimony_better(fitnesses[a], fitnesses[b], options_.tie_tolerance);
    });
    chosen.resize(count);
  }
  std::vector<Individual> kept;
  kept.reserve(count);
  for (std::size_t i : chosen) kept.push_back(i < first.size() ? first[i] : second[i - first.size()]);
  return kept;
}

std::size_t IslandRun::select_parent(const ParetoRanking& ranking, const std::vector<Fitness>& fitnesses,
                                     RandomStream& random) const {
  if (options_.selection == SelectionScheme::tournament) {
    return tournament(fitnesses, options_.tournament_size, options_.tie_tolerance, random);
  }
  std::size_t winner = random.below(members_.size());
  for (std::size_t round = 1; round < options_.tournament_size; ++round) {
    const std::size_t contestant = random.below(members_.size());
    if (ranking.better(contestant, winner)) winner = contestant;
  }
  return winner;
}

std::vector<Individual> IslandRun::breed(std::size_t count) const {
  const std::vector<Fitness> fitnesses = fitnesses_of(members_);
  ParetoRanking ranking;
  if (options_.selection == SelectionScheme::pareto) ranking = rank_by_pareto(fitnesses, options_.objective_count());
  const RandomStream generation_stream = random_.derive(generation_);
  const std::size_t max_length = options_.shape.max_length;
  std::vector<Individual> offspring(count);
  for (std::size_t i = 0; i < count; ++i) {
    RandomStream random = generation_stream.derive(i);
    const Program& mother = members_[select_parent(ranking, fitnesses, random)].program;
    Program& child = offspring[i].program;
    if (random.uniform() < options_.crossover_rate) {
      const Program& father = members_[select_parent(ranking, fitnesses, random)].program;
      const bool subgraph = random.uniform() < options_.subgraph_crossover_share;
      child = subgraph ? subgraph_crossover(mother, father, max_length, random)
                       : string_crossover(mother, father, max_length, random);
      if (random.uniform() < options_.mutation_rate) child = mutate(child, options_.shape, options_.mutation, random);
    } else {
      child = mutate(mother, options_.shape, options_.mutation, random);
    }
  }
  return offspring;
}

void IslandRun::fit_constants_of_best(std::vector<Individual>& offspring) {
  if (options_.constant_fits_per_generation == 0) return;
  std::vector<std::size_t> candidates;
  for (std::size_t i = 0; i < offspring.size(); ++i) {
    if (!live_constant_slots(offspring[i].program).empty()) candidates.push_back(i);
  }
  const std::size_t fits = std::min(candidates.size(), options_.constant_fits_per_generation);
  std::partial_sort(
      candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(fits), candidates.end(),
      [&](std::size_t a, std::size_t b) {
        return parsimony_better(offspring[a].fitness, offspring[b].fitness, options_.tie_tolerance) ||
               (!parsimony_better(offspring[b].fitness, offspring[a].fitness, options_.tie_tolerance) && a < b);
      });
  for (std::size_t k = 0; k < fits; ++k) {
    const std::size_t spare = options_.max_evaluations - std::min(options_.max_evaluations, evaluator_.evaluations());
    ConstantFitOptions fit_options = options_.constants;
    fit_options.max_evaluations = std::min(fit_options.max_evaluations, spare);
    Individual& individual = offspring[candidates[k]];
    const std::size_t before = evaluator_.evaluations();
    const ConstantFitResult fitted =
        fit_constants(individual.program, individual.fitness.error, evaluator_, fit_options);
    constant_fit_evaluations_ += evaluator_.evaluations() - before;
    if (fitted.error < individual.fitness.error) {
      individual.program = fitted.program;
      individual.fitness.error = fitted.error;
      archive_.insert({individual.program, individual.fitness, generation_});
    }
  }
}

bool IslandRun::step() {
  if (options_.restart_after_stall > 0 && stalled_ >= options_.restart_after_stall) {
    restart();
    if (budget_exhausted_ || members_.size() < 2) return false;
  }
  const double previous_best = best_error();
  const bool pareto = options_.selection == SelectionScheme::pareto;
  const std::size_t elites = pareto ? 0 : std::min(options_.elites, members_.size());
  std::vector<Individual> offspring = breed(options_.population_size - elites);
  ++generation_;
  std::size_t evaluated = 0;
  while (evaluated < offspring.size() && evaluate(offspring[evaluated])) ++evaluated;
  offspring.resize(evaluated);
  fit_constants_of_best(offspring);
  if (pareto) {
    members_ = survivors(members_, offspring, options_.population_size);
  } else if (elites + offspring.size() < options_.population_size) {  // cut short by the budget: the best
    members_ = survivors(members_, offspring, options_.population_size);
  } else {
    std::vector<Individual> next = survivors(members_, {}, elites);
    next.insert(next.end(), offspring.begin(), offspring.end());
    members_ = std::move(next);
  }
  track_stall(previous_best);
  return !budget_exhausted_;
}

EvolveResult IslandRun::finish(std::size_t generations_run) {
  EvolveResult result;
  result.population.generation = generation_;
  result.population.stalled = stalled_;
  result.stats.restarts = restarts_;
  result.population.members = std::move(members_);
  result.archive_additions = archive_.entries();
  result.stats.generations = generations_run;
  result.stats.evaluations = evaluator_.evaluations();
  result.stats.constant_fit_evaluations = constant_fit_evaluations_;
  for (const Individual& member : result.population.members) {
    result.stats.best_error = std::min(result.stats.best_error, member.fitness.error);
  }
  result.stats.reached_target = result.stats.best_error <= options_.target_error;
  result.stats.budget_exhausted = budget_exhausted_;
  return result;
}

}  // namespace pbrfit::gp::detail
