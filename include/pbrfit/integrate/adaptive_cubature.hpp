#pragma once
// Globally adaptive cubature over axis-aligned boxes with a tensor-product Gauss-Kronrod 7-15 rule
// (Pesce & Iwanicki 2015, section 3.1): tiles live in a max-heap keyed by their error estimate; the worst
// tile is split in two until the summed error estimate meets the tolerance.
//
// Invariants:
//  - the result depends only on the integrand, the initial tiles and the options (no time, no threads,
//    no randomness), so it is bitwise reproducible;
//  - a tile's error estimate is max over components of |Kronrod - Gauss| of the tensor rules;
//  - result.error_estimate is the sum of the error estimates of all leaf tiles (max over components
//    of the per-component sums);
//  - result.value is summed over the leaf tiles in a fixed order.
#include <array>
#include <cstddef>
#include <span>

namespace pbrfit::integrate {

template <int Dim>
struct Box {
  std::array<double, Dim> lo{};
  std::array<double, Dim> hi{};
};

struct AdaptiveOptions {
  double abs_tolerance = 1e-6;          // target for the summed error estimate
  std::size_t max_evaluations = 50'000'000;  // stop (unconverged) once this many integrand calls are spent
  int max_depth = 48;                   // a tile split this many times is never split again
};

template <int Comp>
struct AdaptiveResult {
  std::array<double, Comp> value{};
  double error_estimate = 0.0;
  std::size_t evaluations = 0;
  std::size_t tiles = 0;   // leaf tiles at the end
  bool converged = false;  // error_estimate <= abs_tolerance
};

// f has the signature std::array<double, Comp>(const std::array<double, Dim>&).
template <int Dim, int Comp, class Integrand>
AdaptiveResult<Comp> integrate_adaptive(const Integrand& f, std::span<const Box<Dim>> initial_tiles,
                                        const AdaptiveOptions& options);

}  // namespace pbrfit::integrate

#include "pbrfit/integrate/adaptive_cubature_impl.hpp"
