#pragma once
// The moves of Nelder-Mead on one working simplex, and the best point they have evaluated.
//
// Invariants: every evaluated point lies in the box; best() is the lowest value measured since the last
// build() or remeasure() started (earliest on ties; the earlier best while nothing has been measured
// since), and the simplex holds it unless the budget interrupted a step; a step whose budget runs out
// leaves the simplex consistent (only measured vertices moved).
#include <optional>
#include <span>
#include <vector>

#include "pbrfit/optimize/bounds.hpp"
#include "pbrfit/optimize/candidate.hpp"
#include "pbrfit/optimize/evaluator.hpp"
#include "pbrfit/optimize/nelder_mead_options.hpp"
#include "simplex.hpp"

namespace pbrfit::optimize::detail {

class SimplexSearch {
 public:
  SimplexSearch(Evaluator& evaluator, const Bounds& bounds, const NelderMeadOptions& options);

  // A fresh simplex around `center` (starting_simplex.hpp); false when the budget ran out first.
  bool build(std::span<const double> center, std::span<const double> relative_steps,
             std::optional<double> center_value);
  // Every vertex measured again at the current tolerance; false when the budget ran out first.
  bool remeasure();
  // One reflection / expansion / contraction / shrink step; false when the budget ran out during it.
  bool step();
  // Relative size <= x_tolerance and the values within the f tolerance (nelder_mead_options.hpp).
  bool collapsed() const;

  const Simplex& simplex() const { return simplex_; }
  const Candidate& best() const { return best_; }

 private:
  bool measure(std::span<const double> x, double& value);
  bool try_point(double coefficient, std::vector<double>& point, double& value);
  void accept(const std::vector<double>& point, double value);
  bool shrink();

  Evaluator& evaluator_;
  const Bounds& bounds_;
  const NelderMeadOptions& options_;
  Simplex simplex_;
  std::vector<double> centroid_;
  std::vector<double> reflected_;
  std::vector<double> other_;  // the expanded or contracted point
  Candidate best_;
  bool best_is_stale_ = true;  // best_ predates the current simplex or tolerance: the next value replaces it
};

}  // namespace pbrfit::optimize::detail
