#pragma once
// Helpers of the kernel-set files (*_isa_<set>.cpp, core/kernel_set.hpp) only: 16 double lanes (or W), exact
// sqrt over them and directions gathered into them. Everything has internal linkage, so that each set's file
// keeps its own copy, compiled for its instruction set (no weak symbol another set could share).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::kernel_lanes {
namespace {

constexpr std::size_t lanes = 16;  // two AVX-512 packets, four AVX2 ones, eight SSE2 ones
constexpr int lane_count = static_cast<int>(lanes);
template <int W>
using LanesOf = Eigen::Array<double, W, 1>;
using Lanes = LanesOf<lane_count>;

// sqrt as a plain loop, which the compiler turns into the set's exact vector sqrt (Eigen's own may take a
// faster, approximate path in some sets). The template serves other widths; pass them as square_root<W>.
template <int W>
LanesOf<W> square_root(const LanesOf<W>& x) {
  LanesOf<W> root;
  for (int i = 0; i < W; ++i) root[i] = std::sqrt(x[i]);
  return root;
}
inline Lanes square_root(const Lanes& x) { return square_root<lane_count>(x); }

template <int W>
struct DirectionsOf {
  LanesOf<W> x, y, z;
};
using Directions = DirectionsOf<lane_count>;

// Up to W directions (n >= 1); lanes past n repeat the last one.
template <int W = lane_count>
DirectionsOf<W> gather(const Vector3* v, std::size_t n) {
  DirectionsOf<W> d;
  for (int i = 0; i < W; ++i) {
    const Vector3& w = v[std::min(static_cast<std::size_t>(i), n - 1)];
    d.x[i] = w.x();
    d.y[i] = w.y();
    d.z[i] = w.z();
  }
  return d;
}

}  // namespace
}  // namespace pbrfit::kernel_lanes
