#pragma once
// The scene LTCs are made for: an infinite plane z = 0 (normal +z) lit by one rectangular area light and seen
// by a pinhole camera. Shared by every render of a plane under a rectangle (the eBRDF scenes of
// ebrdf/plane_scene.hpp, the check render of an LTC table in ltc/table_render.hpp).
//
// Invariants: ray(column, row) is the unit direction through the pixel position (column, row) of a square
// image of `resolution` pixels a side (pixel centres at + 0.5, row 0 at the top, +up in the image);
// plane_hit is nullopt for rays that miss the plane (parallel to it or pointing away).
#include <array>
#include <cstddef>
#include <optional>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

struct PlaneScene {
  Vector3 camera;
  Vector3 forward, right, up;   // orthonormal camera frame
  double tan_half_fov = 0.2679;  // 30 degrees vertical
  std::size_t resolution = 128;
  std::array<Vector3, 4> light;  // vertices in order around the rectangle

  Vector3 ray(double column, double row) const;
  std::optional<Vector3> plane_hit(double column, double row) const;
};

// A camera at `camera` looking at `target`, its up as close to `up_hint` as the view allows.
PlaneScene camera_looking_at(const Vector3& camera, const Vector3& target, const Vector3& up_hint,
                             std::size_t resolution);

}  // namespace pbrfit::ltc
