#pragma once
// An island's population: programs with their fitness and birth generation, the island's generation
// counter (it carries over from one epoch to the next, so generations are numbered across epochs) and
// how long its best error has stalled (for restarts, evolve.hpp).
//
// Invariant: every program is valid for the run's inputs; a fitness with evaluated == false is computed
// by evolve() before anything reads it.
#include <cstdint>
#include <vector>

#include "pbrfit/gp/fitness.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

struct Individual {
  Program program;
  Fitness fitness;
  std::uint64_t born = 0;  // the generation its fitness was first computed in

  bool operator==(const Individual&) const = default;
};

struct Population {
  std::uint64_t generation = 0;  // generations completed so far
  std::uint64_t stalled = 0;     // generations since the best error last improved (or the island restarted)
  std::vector<Individual> members;

  bool operator==(const Population&) const = default;
};

}  // namespace pbrfit::gp
