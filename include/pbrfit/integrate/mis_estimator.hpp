#pragma once
// Deterministic quasi-Monte Carlo integration over the sphere with multiple importance sampling
// (Veach 1997; Pesce & Iwanicki 2015, section 7.3): every strategy k draws the same number n of
// directions, one per point of a fixed low-discrepancy set, and with the balance heuristic
//   integral of F  ~=  (1/n) sum_k sum_i F(x_ki) / sum_j p_j(x_ki).
//
// A strategy is any object with
//   Direction sample(double u1, double u2) const;   // a direction drawn with density pdf
//   double pdf(const Direction& w) const;           // density over solid angle, on the whole sphere
// Invariants: the estimate is a pure function of (F, strategies, points): no randomness, no state;
// samples where every density is 0 contribute nothing; unbiased (for random points) whenever the union
// of the strategies' supports covers the support of F.
#include <array>
#include <cstddef>
#include <span>

#include "pbrfit/integrate/compensated_sum.hpp"

namespace pbrfit::integrate {

template <class Integrand, class Strategy>
double integrate_balance_mis(const Integrand& f, std::span<const Strategy> strategies,
                             std::span<const std::array<double, 2>> points) {
  CompensatedSum sum;
  for (const Strategy& drawing : strategies) {
    for (const auto& u : points) {
      const auto w = drawing.sample(u[0], u[1]);
      double density = 0.0;
      for (const Strategy& other : strategies) density += other.pdf(w);
      if (density > 0.0) sum.add(f(w) / density);
    }
  }
  return points.empty() ? 0.0 : sum.value() / static_cast<double>(points.size());
}

}  // namespace pbrfit::integrate
