#pragma once
// The geometry every engine shares: 3-vectors, 3x3 matrices and an orthonormal frame. Directions are unit
// vectors in the shading frame (z = the surface normal) unless a name says otherwise; matrices act on
// column vectors.
//
// Invariant of Frame: x, y, z are orthonormal and right-handed (x cross y = z), so to_local and from_local
// are inverse rotations and matrix() (columns x, y, z) is a rotation.
#include <Eigen/Dense>

namespace pbrfit {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

struct Frame {
  Vector3 x = Vector3::UnitX();
  Vector3 y = Vector3::UnitY();
  Vector3 z = Vector3::UnitZ();

  // A frame with z = n for a unit vector n (Duff et al. 2017; continuous in n except across n.z = 0).
  static Frame from_z(const Vector3& n);

  Vector3 to_local(const Vector3& w) const { return {w.dot(x), w.dot(y), w.dot(z)}; }
  Vector3 from_local(const Vector3& w) const { return w.x() * x + w.y() * y + w.z() * z; }
  Matrix3 matrix() const;
};

}  // namespace pbrfit
