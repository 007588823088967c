#pragma once
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
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/program.hpp"
#include "pbrfit/gp/program_shape.hpp"

namespace pbrfit::gp {

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

}  // namespace pbrfit::gp
