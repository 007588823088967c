#pragma once
// Where each trial's mutation weight F and crossover probability CR come from (WeightControl).
//
// Invariant: how many random numbers a draw consumes depends on the control mode and the stream only,
// never on objective values.
#include <cstddef>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/optimize/de_options.hpp"
#include "population.hpp"

namespace pbrfit::optimize::detail {

struct TrialControl {
  double weight;     // F
  double crossover;  // CR
};

class TrialControlSource {
 public:
  explicit TrialControlSource(const DeOptions& options) : options_(options) {}

  // Gives every member the starting F and CR of the self-adaptive variant.
  void initialize(Population& population) const;
  void start_generation(RandomStream& random);
  TrialControl draw(const Population& population, std::size_t target, RandomStream& random) const;

 private:
  const DeOptions& options_;
  double generation_weight_ = 0.0;
};

}  // namespace pbrfit::optimize::detail
