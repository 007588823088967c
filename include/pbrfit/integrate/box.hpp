#pragma once
// An axis-aligned box [lo, hi] in Dim dimensions, the unit of work of the adaptive cubature.
#include <array>

namespace pbrfit::integrate {

// Invariant expected by the integrators: lo[d] <= hi[d] for every d.
template <int Dim>
struct Box {
  std::array<double, Dim> lo{};
  std::array<double, Dim> hi{};
};

}  // namespace pbrfit::integrate
