#pragma once
// Internal: the points of the polygon-lighting check's fan integrand (polygon_lighting.cpp) along a whole
// Gauss-Kronrod line of tau at once, as vector code in each kernel set (core/kernel_set.hpp).
//
// Contract: fan_points(set)(line, tau, n, directions, solid_angle, jacobian) for n <= 16 sets, for each
// i < n, with t = tau[i]^4 and the point x = apex + t ((from + s edge) - apex):
//   directions[i] = x / |x|,  solid_angle[i] = |normal . x| / (|x|^2 |x|),
//   jacobian[i] = double_area t 4 tau[i]^2 tau[i] (dA = double_area t dt ds, dt = 4 tau^3 dtau),
// bit for bit in every set: the scalar code's operations in its order, Eigen's 3-vector dot and squared norm
// as (a + b) + c, products left to right, and arithmetic and sqrt rounding the same in every set (no
// contraction into FMA). Lanes past n repeat the last tau and are not stored.
#include <cstddef>

#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc::detail {

// One line of the fan: a triangle (apex, edge from `from` to `from + edge`), the quad's unit normal and s.
struct FanLine {
  Vector3 apex, from, edge, normal;
  double double_area;
  double s;
};

inline constexpr std::size_t fan_line_points = 16;

using FanPoints = void (*)(const FanLine& line, const double* tau, std::size_t n, Vector3* directions,
                           double* solid_angle, double* jacobian);

#define PBRFIT_DECLARE_FAN_POINTS(set)                                                                       \
  namespace set {                                                                                          \
  void fan_points(const FanLine& line, const double* tau, std::size_t n, Vector3* directions, double* solid_angle, \
                  double* jacobian);                                                                       \
  }
PBRFIT_DECLARE_FAN_POINTS(generic)
PBRFIT_DECLARE_FAN_POINTS(avx2)
PBRFIT_DECLARE_FAN_POINTS(avx512)
#undef PBRFIT_DECLARE_FAN_POINTS

inline FanPoints fan_points(KernelSet set) {
  switch (set) {
#if defined(PBRFIT_X86_KERNELS)
    case KernelSet::avx512: return avx512::fan_points;
    case KernelSet::avx2: return avx2::fan_points;
#endif
    default: return generic::fan_points;
  }
}

}  // namespace pbrfit::ltc::detail
