#include "pbrfit/ltc/plane_scene.hpp"

namespace pbrfit::ltc {

PlaneScene camera_looking_at(const Vector3& camera, const Vector3& target, const Vector3& up_hint,
                             std::size_t resolution) {
  PlaneScene s;
  s.camera = camera;
  s.forward = (target - camera).normalized();
  s.right = s.forward.cross(up_hint).normalized();
  s.up = s.right.cross(s.forward);
  s.resolution = resolution;
  return s;
}

Vector3 PlaneScene::ray(double column, double row) const {
  const double n = double(resolution);
  const double x = (2.0 * column / n - 1.0) * tan_half_fov;
  const double y = (1.0 - 2.0 * row / n) * tan_half_fov;
  return (forward + x * right + y * up).normalized();
}

std::optional<Vector3> PlaneScene::plane_hit(double column, double row) const {
  const Vector3 d = ray(column, row);
  if (d.z() >= -1e-9) return std::nullopt;
  return camera + (-camera.z() / d.z()) * d;
}

}  // namespace pbrfit::ltc
