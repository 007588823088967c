#pragma once
// One DE trial vector: mutation by the configured strategy, binomial crossover with the target, then the
// bound handling (de_options.hpp has the formulas).
//
// Invariants: the trial lies in the box; fixed dimensions keep the target's value; the forced crossover
// dimension j_rand is drawn among the free dimensions; the population holds at least 5 members.
#include <cstddef>
#include <span>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/de_options.hpp"
#include "population.hpp"
#include "trial_control.hpp"

namespace pbrfit::optimize::detail {

struct TrialContext {
  const Population& population;
  const Bounds& bounds;
  const DeOptions& options;
  std::span<const std::size_t> free_dimensions;  // not empty
  std::span<const std::size_t> ranking;          // members by increasing value (best first)
};

void build_trial(const TrialContext& context, std::size_t target, TrialControl control, RandomStream& random,
                 std::span<double> trial);

}  // namespace pbrfit::optimize::detail
