#pragma once
// Optional integrand fast path: hoisting work that depends only on the first coordinate.
//
// An integrand f may provide f.bind_outer(x0), returning a callable g with g(x) == f(x) for every x
// with x[0] == x0. The tensor rule then binds once per distinct first coordinate of a tile's grid
// (15 per tile) and evaluates the remaining 15^(Dim-1) samples of that slice through g.
#include <array>
#include <concepts>

namespace pbrfit::integrate {

template <class F, int Dim, int Comp>
concept OuterBindable = requires(const F& f, double x0, const std::array<double, Dim>& x) {
  { f.bind_outer(x0)(x) } -> std::convertible_to<std::array<double, Comp>>;
};

}  // namespace pbrfit::integrate
