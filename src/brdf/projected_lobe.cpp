#include "pbrfit/brdf/projected_lobe.hpp"

#include <cmath>

#include "pbrfit/brdf/ggx_lobe.hpp"

namespace pbrfit::brdf {

double ProjectedLobe::density(double x, double y) const {
  const Vector3 to_point = Vector3(x, y, 0.0) - origin;
  const double r = to_point.norm();
  const Vector3 w = to_point / r;
  const Frame frame = Frame::from_z(axis);
  // rho at normal view in the lobe's frame: the view is the lobe axis itself.
  const double rho = ggx_cosine_weighted(alpha, Vector3::UnitZ(), frame.to_local(w));
  return rho * origin.z() / (r * r * r);
}

ProjectedLobe perpendicular_lobe(double alpha, double distance, double centre_x, double centre_y) {
  return ProjectedLobe{alpha, Vector3(centre_x, centre_y, distance), -Vector3::UnitZ()};
}

ProjectedLobe tilted_lobe(double alpha, double angle, double distance) {
  const Vector3 axis(std::sin(angle), 0.0, -std::cos(angle));
  return ProjectedLobe{alpha, -distance * axis, axis};
}

}  // namespace pbrfit::brdf
