#include <cmath>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit {

Frame Frame::from_z(const Vector3& n) {
  const double sign = std::copysign(1.0, n.z());
  const double a = -1.0 / (sign + n.z());
  const double b = n.x() * n.y() * a;
  Frame frame;
  frame.x = Vector3(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  frame.y = Vector3(b, sign + n.y() * n.y() * a, -n.y());
  frame.z = n;
  return frame;
}

Matrix3 Frame::matrix() const {
  Matrix3 columns;
  columns << x, y, z;
  return columns;
}

}  // namespace pbrfit
