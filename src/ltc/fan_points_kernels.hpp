// The fan integrand's points (fan_points.hpp) of one kernel set. Included once by each
// fan_points_isa_<set>.cpp, inside a namespace named by PBRFIT_KERNEL_ISA, so that the sets' copies never
// meet at link time.
#ifndef PBRFIT_KERNEL_ISA
#error "fan_points_kernels.hpp is included by the fan_points_isa_<set>.cpp files only"
#endif
#include <Eigen/Core>
#include <algorithm>

#include "fan_points.hpp"
#include "pbrfit/geometry/kernel_lanes.hpp"

namespace pbrfit::ltc::detail::PBRFIT_KERNEL_ISA {

[[gnu::flatten]] void fan_points(const FanLine& line, const double* tau, std::size_t n, Vector3* directions,
                                 double* solid_angle, double* jacobian) {
  using kernel_lanes::lanes;
  using kernel_lanes::Lanes;
  using kernel_lanes::square_root;
  static_assert(lanes == fan_line_points);
  Lanes u;
  for (std::size_t i = 0; i < lanes; ++i) u[Eigen::Index(i)] = tau[std::min(i, n - 1)];
  const Lanes u2 = u * u;
  const Lanes t = u2 * u2;
  // from + s edge - apex, the same for every point of the line.
  const Vector3& a = line.apex;
  const double bx = (line.from.x() + line.s * line.edge.x()) - a.x();
  const double by = (line.from.y() + line.s * line.edge.y()) - a.y();
  const double bz = (line.from.z() + line.s * line.edge.z()) - a.z();
  const Lanes x = a.x() + t * bx;
  const Lanes y = a.y() + t * by;
  const Lanes z = a.z() + t * bz;
  const Lanes length2 = (x * x + y * y) + z * z;
  const Lanes length = square_root(length2);
  const Lanes dx = x / length, dy = y / length, dz = z / length;
  const Lanes along_normal = (line.normal.x() * x + line.normal.y() * y) + line.normal.z() * z;
  const Lanes solid = along_normal.abs() / (length2 * length);
  const Lanes area = (((line.double_area * t) * 4.0) * u2) * u;
  for (std::size_t i = 0; i < n; ++i) {
    const auto l = Eigen::Index(i);
    directions[i] = Vector3(dx[l], dy[l], dz[l]);
    solid_angle[i] = solid[l];
    jacobian[i] = area[l];
  }
}

}  // namespace pbrfit::ltc::detail::PBRFIT_KERNEL_ISA
