#pragma once
// Variation and selection of linear GP programs: random programs and their parts, mutation, crossover, and
// tournament selection with parsimony pressure (the alternative to Pareto selection, pareto.hpp).
// Every operator draws its random numbers from the stream it is given, so a program's offspring are a
// pure function of (parents, stream).
#include <cstddef>
#include <span>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/fitness.hpp"
#include "pbrfit/gp/program.hpp"
#include "pbrfit/gp/program_shape.hpp"

namespace pbrfit::gp {

// Random programs and random parts of programs, drawn from a shape (program_shape.hpp). Every result is
// valid for shape.input_count inputs and draws only operators of shape.operators.
//
// A program of uniform length in [initial_min_length, initial_max_length].
Program random_program(const ProgramShape& shape, RandomStream& random);

// An operand for an instruction at `position`: an earlier result, an input or a constant (its value is
// written to `constant`, 0 otherwise).
Operand random_operand(const ProgramShape& shape, std::size_t position, double& constant, RandomStream& random);

// An instruction at `position` with a random operator and random operands.
Instruction random_instruction(const ProgramShape& shape, std::size_t position, RandomStream& random);

// Point and length mutations of a linear program. Each picks a LIVE instruction (mutating an intron would
// change nothing the fitness sees):
//  - operator: another operator of the shape; operands kept where the arity allows, new ones drawn;
//  - operand: one operand redrawn (an earlier result, an input or a constant);
//  - constant: one constant perturbed by a Gaussian step of constant_sigma * max(1, |value|) (an operand
//    mutation when the live code has no constant);
//  - insertion: a new instruction wraps one operand of a live instruction (x -> op(x, ...)), so it is live
//    at once; only below shape.max_length;
//  - deletion: a live instruction is bypassed: its users read its first operand instead.
// Contract: the result is valid for the shape's inputs and no longer than max(shape.max_length, the
// parent's length); a mutation that cannot apply (deletion of a one-instruction program, insertion at the
// maximum length) falls back to an operand mutation.
//
enum class MutationKind { operator_change, operand_change, constant_step, insertion, deletion };

struct MutationOptions {
  // Relative weights of the kinds; at least one > 0.
  double operator_weight = 1.0;
  double operand_weight = 1.0;
  double constant_weight = 1.0;
  double insertion_weight = 1.0;
  double deletion_weight = 1.0;
  double constant_sigma = 0.1;
};

Program mutate(const Program& parent, const ProgramShape& shape, const MutationOptions& options, RandomStream& random);
Program mutate(const Program& parent, MutationKind kind, const ProgramShape& shape, const MutationOptions& options,
               RandomStream& random);

// Crossovers on the instruction string (Pesce & Iwanicki 2015, section 5.2). Both keep every reference
// pointing to an earlier instruction, so children are valid whenever the parents are.
//  - string crossover: the child is the mother's instructions before a cut and the father's from the cut
//    on. The father's references below the cut now read the mother's instructions at those positions
//    (a blind copy of memory, as the course describes);
//  - subgraph crossover: a live instruction of the mother is replaced by the live subgraph that computes a
//    live instruction of the father (copied as a contiguous run of instructions); the mother's users of
//    the replaced instruction read the subgraph's root. The analogue of tree GP's subtree crossover.
// Contract: a child is never longer than max_length; when no cut or splice fits, the mother is returned.
Program string_crossover(const Program& mother, const Program& father, std::size_t max_length, RandomStream& random);
Program subgraph_crossover(const Program& mother, const Program& father, std::size_t max_length, RandomStream& random);

// Tournament selection with parsimony pressure (the alternative to Pareto selection): `size` contestants
// drawn uniformly with replacement; the lowest error wins, and errors within `tie_tolerance` (relative)
// of each other tie, which the lower cost breaks (lexicographic parsimony), then the earlier draw.
// a is better than b: lower error beyond the tolerance, else lower cost.
bool parsimony_better(const Fitness& a, const Fitness& b, double tie_tolerance);

std::size_t tournament(std::span<const Fitness> fitnesses, std::size_t size, double tie_tolerance,
                       RandomStream& random);

}  // namespace pbrfit::gp
