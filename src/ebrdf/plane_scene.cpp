#include "pbrfit/ebrdf/plane_scene.hpp"

namespace pbrfit::ebrdf {

PlaneScene make_plane_scene(SceneView view, double h, std::size_t resolution) {
  const Vector3 centre(0.5, 0.5, 0.0);
  if (view == SceneView::top) {
    PlaneScene s = ltc::camera_looking_at(centre + Vector3(0, 0, h), centre, Vector3::UnitY(), resolution);
    const Vector3 c = centre + Vector3(0.1 * h, 0.0, 0.8 * h);
    const double a = 0.15 * h;
    s.light = {c + Vector3(-a, -a, 0), c + Vector3(a, -a, 0), c + Vector3(a, a, 0), c + Vector3(-a, a, 0)};
    return s;
  }
  PlaneScene s = ltc::camera_looking_at(centre + Vector3(0, -h, 0.25 * h), centre, Vector3::UnitZ(), resolution);
  const Vector3 c = centre + Vector3(0.0, 0.8 * h, 0.15 * h);
  const double w = 0.3 * h, t = 0.1 * h;
  s.light = {c + Vector3(-w, 0, -t), c + Vector3(w, 0, -t), c + Vector3(w, 0, t), c + Vector3(-w, 0, t)};
  return s;
}

const char* scene_view_name(SceneView view) { return view == SceneView::top ? "top" : "grazing"; }

}  // namespace pbrfit::ebrdf
