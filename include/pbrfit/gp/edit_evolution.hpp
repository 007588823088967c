#pragma once
// One generation of an island of genBRDF (Brady et al., section 3.2, step 4) over edit genomes
// (tree_edit.hpp): n/2 parents chosen by tournaments of `tournament_size` (lower error wins; ties go to the
// smaller tree, then to the earlier member), paired in the order chosen; each pair's one-point crossover
// gives two offspring ⟨A1, B2⟩ and ⟨B1, A2⟩ (cut points drawn per parent); every parent and every offspring
// then appends one random edit. The next population is the n/2 parents followed by the n/2 offspring.
//
// Contract: a pure function of (population, options, random stream key): slot s of the next generation draws
// from random.derive(s), the tournaments from random.derive(2^32); population sizes are even and >= 2;
// genomes longer than max_genome keep their first max_genome - 1 edits before the new one is appended.
#include <cstddef>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/fitness.hpp"
#include "pbrfit/gp/tree_edit.hpp"

namespace pbrfit::gp {

using Genome = std::vector<Edit>;

struct EditIndividual {
  Genome genome;
  Fitness fitness;  // error and cost (the tree's size)
};

struct EditEvolutionOptions {
  std::size_t tournament_size = 8;
  std::size_t max_genome = 512;
};

std::vector<Genome> breed_island(std::span<const EditIndividual> population, const EditEvolutionOptions& options,
                                 const RandomStream& random);
// n genomes of one random edit each (section 3.2, step 2), slot s drawn from random.derive(s).
std::vector<Genome> initial_genomes(std::size_t n, const RandomStream& random);

}  // namespace pbrfit::gp
