#include "pbrfit/ebrdf/plane_scene.hpp"

namespace pbrfit::ebrdf {
namespace {


PlaneScene looking_at(const Vector3& camera, const Vector3& target, const Vector3& up_hint, std::size_t resolution) {
  PlaneScene s;
  s.camera = camera;
  s.forward = (target - camera).normalized();
  s.right = s.forward.cross(up_hint).normalized();
  s.up = s.right.cross(s.forward);
  s.resolution = resolution;
  return s;
}

}  // namespace

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

PlaneScene make_plane_scene(SceneView view, double h, std::size_t resolution) {
  const Vector3 centre(0.5, 0.5, 0.0);
  if (view == SceneView::top) {
    PlaneScene s = looking_at(centre + Vector3(0, 0, h), centre, Vector3::UnitY(), resolution);
    const Vector3 c = centre + Vector3(0.1 * h, 0.0, 0.8 * h);
    const double a = 0.15 * h;
    s.light = {c + Vector3(-a, -a, 0), c + Vector3(a, -a, 0), c + Vector3(a, a, 0), c + Vector3(-a, a, 0)};
    return s;
  }
  PlaneScene s = looking_at(centre + Vector3(0, -h, 0.25 * h), centre, Vector3::UnitZ(), resolution);
  const Vector3 c = centre + Vector3(0.0, 0.8 * h, 0.15 * h);
  const double w = 0.3 * h, t = 0.1 * h;
  s.light = {c + Vector3(-w, 0, -t), c + Vector3(w, 0, -t), c + Vector3(w, 0, t), c + Vector3(-w, 0, t)};
  return s;
}

const char* scene_view_name(SceneView view) { return view == SceneView::top ? "top" : "grazing"; }

}  // namespace pbrfit::ebrdf
