#include "trial_vector.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "random_draws.hpp"

namespace pbrfit::optimize::detail {
namespace {

// A member index different from every index in `taken`.
std::size_t draw_other(RandomStream& random, std::size_t size, std::initializer_list<std::size_t> taken) {
  for (;;) {
    const std::size_t index = index_below(random, size);
    if (std::find(taken.begin(), taken.end(), index) == taken.end()) return index;
  }
}

// The mutant is base + F (plus - minus) + F (toward - target), the last term for current_to_pbest only.
struct Donors {
  std::size_t base;
  std::size_t plus;
  std::size_t minus;
  std::size_t toward;
};

Donors pick_donors(const TrialContext& context, std::size_t target, RandomStream& random) {
  const std::size_t size = context.population.size;
  if (context.options.strategy == DeStrategy::current_to_pbest) {
    const auto top = static_cast<double>(size) * context.options.pbest_fraction;
    const std::size_t pool = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(top)), 2, size);
    const std::size_t toward = context.ranking[index_below(random, pool)];
    const std::size_t plus = draw_other(random, size, {target});
    return {target, plus, draw_other(random, size, {target, plus}), toward};
  }
  const std::size_t first = draw_other(random, size, {target});
  const std::size_t second = draw_other(random, size, {target, first});
  if (context.options.strategy == DeStrategy::best_1) return {context.ranking[0], first, second, target};
  return {first, second, draw_other(random, size, {target, first, second}), target};
}

double repair(const Bounds& bounds, std::size_t d, double value, BoundHandling handling, RandomStream& random) {
  if (value >= bounds.lower[d] && value <= bounds.upper[d]) return value;
  if (handling == BoundHandling::reinitialize) return uniform_in(random, bounds.lower[d], bounds.upper[d]);
  return std::clamp(value, bounds.lower[d], bounds.upper[d]);
}

}  // namespace

void build_trial(const TrialContext& context, std::size_t target, TrialControl control, RandomStream& random,
                 std::span<double> trial) {
  const Population& population = context.population;
  const Donors donors = pick_donors(context, target, random);
  const auto current = population.row(target);
  const auto base = population.row(donors.base);
  const auto plus = population.row(donors.plus);
  const auto minus = population.row(donors.minus);
  const auto toward = population.row(donors.toward);
  std::copy(current.begin(), current.end(), trial.begin());
  const std::size_t forced = context.free_dimensions[index_below(random, context.free_dimensions.size())];
  for (std::size_t d : context.free_dimensions) {
    if (d != forced && !(random.uniform() < control.crossover)) continue;
    const double mutant =
        base[d] + control.weight * (plus[d] - minus[d]) + control.weight * (toward[d] - current[d]);
    trial[d] = repair(context.bounds, d, mutant, context.options.bound_handling, random);
  }
}

}  // namespace pbrfit::optimize::detail
