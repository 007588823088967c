#pragma once
// Crossovers on the instruction string (Pesce & Iwanicki 2015, section 5.2). Both keep every reference
// pointing to an earlier instruction, so children are valid whenever the parents are.
//  - string crossover: the child is the mother's instructions before a cut and the father's from the cut
//    on. The father's references below the cut now read the mother's instructions at those positions
//    (a blind copy of memory, as the course describes);
//  - subgraph crossover: a live instruction of the mother is replaced by the live subgraph that computes a
//    live instruction of the father (copied as a contiguous run of instructions); the mother's users of
//    the replaced instruction read the subgraph's root. The analogue of tree GP's subtree crossover.
// Contract: a child is never longer than max_length; when no cut or splice fits, the mother is returned.
#include <cstddef>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

Program string_crossover(const Program& mother, const Program& father, std::size_t max_length, RandomStream& random);
Program subgraph_crossover(const Program& mother, const Program& father, std::size_t max_length, RandomStream& random);

}  // namespace pbrfit::gp
