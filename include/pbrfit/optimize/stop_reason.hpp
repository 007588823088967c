#pragma once
// Why an optimizer returned. Every result carries exactly one.
namespace pbrfit::optimize {

enum class StopReason {
  budget,           // the evaluation budget (or the phase's share of it) is spent
  iteration_limit,  // DE's generation limit or Nelder-Mead's iteration limit
  target,           // the best value reached the caller's target
  stagnation,       // DE's best did not improve enough for the configured number of generations
  spread,           // DE's population shrank below the configured relative spread
  converged,        // Nelder-Mead's simplex collapsed and restarts brought no further progress
};

const char* to_string(StopReason reason);

}  // namespace pbrfit::optimize
