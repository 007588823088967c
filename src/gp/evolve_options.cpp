#include "pbrfit/gp/evolve.hpp"

#include <stdexcept>

namespace pbrfit::gp {
namespace {

bool is_share(double p) { return p >= 0.0 && p <= 1.0; }

}  // namespace

void validate(const EvolveOptions& options) {
  validate(options.shape);
  if (options.population_size < 2) throw std::invalid_argument("a population needs at least two members");
  if (options.tournament_size < 1) throw std::invalid_argument("a tournament needs at least one contestant");
  if (options.elites >= options.population_size)
    throw std::invalid_argument("elites must be fewer than the population");
  if (!is_share(options.crossover_rate) || !is_share(options.subgraph_crossover_share) ||
      !is_share(options.mutation_rate)) {
    throw std::invalid_argument("crossover and mutation rates must be in [0, 1]");
  }
  const MutationOptions& m = options.mutation;
  for (double w : {m.operator_weight, m.operand_weight, m.constant_weight, m.insertion_weight, m.deletion_weight}) {
    if (!(w >= 0.0)) throw std::invalid_argument("mutation weights must be >= 0");
  }
  if (m.operator_weight + m.operand_weight + m.constant_weight + m.insertion_weight + m.deletion_weight <= 0.0) {
    throw std::invalid_argument("at least one mutation weight must be positive");
  }
  if (!(options.tie_tolerance >= 0.0)) throw std::invalid_argument("the tie tolerance must be >= 0");
}

}  // namespace pbrfit::gp
