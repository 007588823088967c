#pragma once
// The function an optimizer minimizes. It receives a point x (one value per dimension, valid only during
// the call) and the accuracy the optimizer currently needs: `tolerance`, an absolute error bound the
// objective may spend on its own numerics (an integration tolerance, a sample count). Within one run the
// tolerance never grows, and every value an optimizer reports as best was computed at its schedule's
// final tolerance (tolerance_schedule.hpp).
//
// Contract: for fixed (x, tolerance) the callable returns the same value every time. It may return +inf
// or NaN for an infeasible point; the optimizers rank both as worse than every finite value.
// A callable that takes only x is accepted as well and simply never sees the tolerance.
#include <concepts>
#include <functional>
#include <span>
#include <type_traits>
#include <utility>

namespace pbrfit::optimize {

class Objective;

template <class F>
concept ToleranceAwareObjective =
    !std::same_as<std::remove_cvref_t<F>, Objective> && std::invocable<F&, std::span<const double>, double>;

template <class F>
concept PlainObjective = !ToleranceAwareObjective<F> && std::invocable<F&, std::span<const double>>;

class Objective {
 public:
  template <ToleranceAwareObjective F>
  Objective(F f) : call_(std::move(f)) {}

  template <PlainObjective F>
  Objective(F f) : call_([plain = std::move(f)](std::span<const double> x, double) mutable { return plain(x); }) {}

  double operator()(std::span<const double> x, double tolerance) const { return call_(x, tolerance); }

 private:
  std::function<double(std::span<const double>, double)> call_;
};

}  // namespace pbrfit::optimize
