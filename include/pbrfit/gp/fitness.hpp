#pragma once
// A program's objectives (Pesce & Iwanicki 2015, section 5.1), all minimized: error (error_measure.hpp),
// cost (cost_model.hpp) and, when a run tracks it, the number of piecewise operators. Runs compare 2 or 3
// of them (objective_count).
//
// Invariants: error >= 0 or worst_error (+inf), never NaN; cost and piecewise finite and >= 0. A fitness
// that was never computed has evaluated == false and compares as the worst.
#include <array>
#include <cstddef>

#include "pbrfit/gp/error_measure.hpp"

namespace pbrfit::gp {

struct Fitness {
  double error = worst_error;
  double cost = 0.0;
  double piecewise = 0.0;
  bool evaluated = false;

  double objective(std::size_t k) const { return k == 0 ? error : (k == 1 ? cost : piecewise); }
  bool operator==(const Fitness&) const = default;
};

// a is no worse than b in every one of the first `objective_count` objectives and better in one.
bool dominates(const Fitness& a, const Fitness& b, std::size_t objective_count);
// Same objective values in the first `objective_count` objectives.
bool same_objectives(const Fitness& a, const Fitness& b, std::size_t objective_count);

}  // namespace pbrfit::gp
