#pragma once
// Helpers of the kernel-set files (*_isa_<set>.cpp, core/kernel_set.hpp) only: 16 double lanes, exact sqrt
// over them and directions gathered into them. Everything has internal linkage, so that each set's file
// keeps its own copy, compiled for its instruction set (no weak symbol another set could share).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::kernel_lanes {
namespace {

constexpr std::size_t lanes = 16;  // two AVX-512 packets, four AVX2 ones, eight SSE2 ones
using Lanes = Eigen::Array<double, lanes, 1>;

// sqrt as a plain loop, which the compiler turns into the set's exact vector sqrt (Eigen's own may take a
// faster, approximate path in some sets).
inline Lanes square_root(const Lanes& x) {
  Lanes root;
  for (std::size_t i = 0; i < lanes; ++i) root[i] = std::sqrt(x[i]);
  return root;
}

struct Directions {
  Lanes x, y, z;
};

// Up to 16 directions (n >= 1); lanes past n repeat the last one.
inline Directions gather(const Vector3* v, std::size_t n) {
  Directions d;
  for (std::size_t i = 0; i < lanes; ++i) {
    const Vector3& w = v[std::min(i, n - 1)];
    d.x[i] = w.x();
    d.y[i] = w.y();
    d.z[i] = w.z();
  }
  return d;
}

}  // namespace
}  // namespace pbrfit::kernel_lanes
