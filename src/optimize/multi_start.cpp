#include <stdexcept>

#include "pbrfit/optimize/nelder_mead.hpp"

namespace pbrfit::optimize {

NelderMeadResult multi_start_nelder_mead(Evaluator& evaluator, const Bounds& bounds,
                                         std::span<const std::vector<double>> starts,
                                         const NelderMeadOptions& options) {
  if (starts.empty()) throw std::invalid_argument("optimize: multi-start Nelder-Mead needs a start point");
  NelderMeadResult total;
  total.starts_run = 0;
  const std::size_t first_evaluation = evaluator.used();
  for (std::size_t k = 0; k < starts.size() && !evaluator.exhausted(); ++k) {
    const NelderMeadResult run = nelder_mead(evaluator, bounds, starts[k], options);
    total.iterations += run.iterations;
    total.restarts += run.restarts;
    total.starts_run += run.starts_run;
    total.stop = run.stop;
    if (total.best.x.empty() || run.best.value < total.best.value) {
      total.best = run.best;
      total.winning_start = k;
    }
    if (run.stop == StopReason::target) break;
  }
  total.evaluations = evaluator.used() - first_evaluation;
  return total;
}

}  // namespace pbrfit::optimize
