#pragma once
// Globally adaptive cubature over axis-aligned boxes with a tensor-product Gauss-Kronrod 7-15 rule
// (Pesce & Iwanicki 2015, section 3.1): tiles live in a max-heap keyed by their error estimate; the worst
// tile is split in half until the summed error estimate meets the tolerance.
//
// Invariants:
//  - the result depends only on the integrand, the initial tiles and the options (no time, no threads,
//    no randomness), so it is bitwise reproducible;
//  - a tile's error estimate is max over components of |Kronrod - Gauss| of the tensor rules; a
//    non-finite estimate counts as +infinity;
//  - a tile is split along the axis whose Kronrod-vs-Gauss indicator (Gauss along that axis only) is
//    largest, lowest axis on ties; heap ties go to the earliest-created tile;
//  - result.error_estimate is the sum over all leaf tiles of their error estimates, and
//    result.value the per-component sum of their Kronrod values, both summed with compensation over
//    the leaves in creation order;
//  - every initial tile is evaluated (15^Dim samples each) even if that exceeds max_evaluations; a split
//    happens only if its two children fit in the remaining budget;
//  - the tolerance is max(abs_tolerance, rel_tolerance * the largest |component| of the running value);
//    with rel_tolerance = 0 (the default) it is abs_tolerance alone.
#include <array>
#include <cstddef>
#include <span>

#include "pbrfit/integrate/box.hpp"
#include "pbrfit/integrate/outer_binding.hpp"

namespace pbrfit::integrate {

struct AdaptiveOptions {
  double abs_tolerance = 1e-6;               // target for the summed error estimate
  std::size_t max_evaluations = 50'000'000;  // stop (unconverged) before spending more integrand calls
  int max_depth = 48;                        // a tile split this many times is never split again
  double rel_tolerance = 0.0;                // ... or this fraction of the integral, whichever is larger
};

template <int Comp>
struct AdaptiveResult {
  std::array<double, Comp> value{};
  double error_estimate = 0.0;
  std::size_t evaluations = 0;
  std::size_t tiles = 0;   // leaf tiles at the end
  bool converged = false;  // error_estimate <= abs_tolerance
};

// f has the signature std::array<double, Comp>(const std::array<double, Dim>&); it may additionally
// offer bind_outer (see outer_binding.hpp) to hoist work that depends only on x[0].
template <int Dim, int Comp, class Integrand>
AdaptiveResult<Comp> integrate_adaptive(const Integrand& f, std::span<const Box<Dim>> initial_tiles,
                                        const AdaptiveOptions& options);

}  // namespace pbrfit::integrate

#include "pbrfit/integrate/adaptive_cubature_impl.hpp"
