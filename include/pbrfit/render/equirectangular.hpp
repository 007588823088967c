#pragma once
// Equirectangular (latitude-longitude) coordinates of world directions, +y up: theta is the polar angle
// from +y in [0, pi], phi the azimuth about +y measured from +z towards +x, in [0, 2 pi). An H x W image
// covers the sphere with texel (column c, row r) holding theta in [r, r+1) pi / H and phi in
// [c, c+1) 2 pi / W.
//
// Invariants: direction_of(angles_of(d)) == d up to rounding for unit d; texel_of always returns a texel
// inside the image (theta = pi falls in the last row, phi near 2 pi in the last column).
#include <cstddef>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::render {

struct LatLong {
  double theta = 0.0, phi = 0.0;
};

struct Texel {
  std::size_t column = 0, row = 0;
};

LatLong angles_of(const Vector3& direction);
Vector3 direction_of(const LatLong& angles);
Texel texel_of(const LatLong& angles, std::size_t width, std::size_t height);
// The solid angle of a texel of row `row`: (cos(row pi/H) - cos((row+1) pi/H)) 2 pi / W; they sum to 4 pi.
double texel_solid_angle(std::size_t row, std::size_t width, std::size_t height);
// The angles of a texel's centre.
LatLong texel_centre(const Texel& texel, std::size_t width, std::size_t height);

}  // namespace pbrfit::render
