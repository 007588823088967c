#pragma once
// The state of one evolve() call: the population, the evaluator (with its budget), the archive of what
// this call evaluated, and the generation loop.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/evolve.hpp"
#include "pbrfit/gp/fitness_evaluator.hpp"
#include "pbrfit/gp/pareto.hpp"

namespace pbrfit::gp::detail {

class IslandRun {
 public:
  IslandRun(const EvolveOptions& options, const Dataset& dataset, const RandomStream& random, std::uint64_t generation,
            std::uint64_t stalled);

  // Evaluates what needs it, merges, and cuts back to the population size.
  void admit(std::span<const Individual> members, std::span<const Individual> migrants);
  // One generation; false when the budget ended it early (it still selects from what was evaluated).
  bool step();
  bool reached_target() const;
  EvolveResult finish(std::size_t generations_run);

 private:
  bool evaluate(Individual& individual);  // false when the budget is spent
  double best_error() const;
  // Counts a generation with `previous_best`; restarts the island when it has stalled long enough.
  void track_stall(double previous_best);
  void restart();
  void fit_constants_of_best(std::vector<Individual>& offspring);
  std::vector<Individual> breed(std::size_t count) const;
  // The best `count` of first and second together, by the selection scheme.
  std::vector<Individual> survivors(std::span<const Individual> first, std::span<const Individual> second,
                                    std::size_t count) const;
  std::size_t select_parent(const ParetoRanking& ranking, const std::vector<Fitness>& fitnesses,
                            RandomStream& random) const;

  const EvolveOptions& options_;
  RandomStream random_;
  FitnessEvaluator evaluator_;
  ParetoArchive archive_;
  std::uint64_t generation_;
  std::uint64_t stalled_;
  std::size_t restarts_ = 0;
  std::vector<Individual> members_;
  std::size_t constant_fit_evaluations_ = 0;
  bool budget_exhausted_ = false;
};

}  // namespace pbrfit::gp::detail
