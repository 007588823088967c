#include "pbrfit/gp/parameter_fit.hpp"

#include <algorithm>

#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"

namespace pbrfit::gp {

template <class T>
ParameterFitResult fit_parameters(const Program& program, std::span<const std::vector<ConstantSlot>> slots,
                                  BatchInterpreter<T>& interpreter, const ParameterFitOptions& options,
                                  const RandomStream& random, std::span<const double> previous) {
  const std::size_t n = slots.size();
  optimize::Bounds box{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  for (std::size_t k = 0; k < n; ++k)
    if (!slots[k].empty()) box.lower[k] = options.lower, box.upper[k] = options.upper;
  Program trial = program;
  std::size_t evaluations = 0;
  const optimize::Objective error = [&](std::span<const double> x) {
    set_parameters(trial, slots, x);
    ++evaluations;
    return interpreter.error(trial);
  };
  ParameterFitResult best{std::vector<double>(n, 0.0), worst_error, 0};
  optimize::NelderMeadOptions search;
  // The first simplex spans a tenth of the start range: the box is often far wider than the values.
  search.initial_step = std::max(0.1 * (options.start_upper - options.start_lower), 1e-3) / (options.upper - options.lower);
  search.max_restarts = 2;
  for (std::size_t s = 0; s < options.starts; ++s) {
    RandomStream draw = random.derive(s);
    std::vector<double> start(n, 0.0);
    const bool warm = s == 0 && options.warm_start && previous.size() == n;
    for (std::size_t k = 0; k < n; ++k)
      if (!slots[k].empty())
        start[k] = warm ? std::clamp(previous[k], options.lower, options.upper)
                        : options.start_lower + (options.start_upper - options.start_lower) * draw.uniform();
    const auto run = optimize::nelder_mead(error, box, start, search, options.evaluations_per_start);
    if (!run.best.x.empty() && run.best.value < best.error) best = {run.best.x, run.best.value, 0};
  }
  best.evaluations = evaluations;
  return best;
}

template ParameterFitResult fit_parameters<float>(const Program&, std::span<const std::vector<ConstantSlot>>,
                                                  BatchInterpreter<float>&, const ParameterFitOptions&, const RandomStream&,
                                                  std::span<const double>);
template ParameterFitResult fit_parameters<double>(const Program&, std::span<const std::vector<ConstantSlot>>,
                                                   BatchInterpreter<double>&, const ParameterFitOptions&, const RandomStream&,
                                                   std::span<const double>);

}  // namespace pbrfit::gp
