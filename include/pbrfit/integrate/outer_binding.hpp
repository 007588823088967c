#pragma once
// Optional integrand fast paths: hoisting work that depends only on the first coordinate, and evaluating
// a whole line of the rule at once.
//
// An integrand f may provide f.bind_outer(x0), returning a callable g with g(x) == f(x) for every x
// with x[0] == x0. The tensor rule then binds once per distinct first coordinate of a tile's grid
// (15 per tile) and evaluates the remaining 15^(Dim-1) samples of that slice through g.
//
// A bound slice g may also provide g.line(x, last, out): the values at the 15 points that share x's
// coordinates but the last, x[Dim-1] = last[i] for i = 0..14, written as out[i * Comp + c]. The rule
// then takes every line of the grid this way, so that the integrand can run as vector code over all 15
// nodes. The values must depend on the point alone, never on its place in the line; they may differ
// from g(x) only where the line uses other (vector) transcendental functions than g does.
#include <array>
#include <concepts>

namespace pbrfit::integrate {

template <class F, int Dim, int Comp>
concept OuterBindable = requires(const F& f, double x0, const std::array<double, Dim>& x) {
  { f.bind_outer(x0)(x) } -> std::convertible_to<std::array<double, Comp>>;
};

template <class G, int Dim>
concept LineEvaluable = requires(const G& g, const std::array<double, Dim>& x, const double* last, double* out) {
  g.line(x, last, out);
};

}  // namespace pbrfit::integrate
