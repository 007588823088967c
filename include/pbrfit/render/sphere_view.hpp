#pragma once
// The camera of the sphere renders: an orthographic camera on the +z axis looking along -z at the unit
// sphere centred at the origin. Its resolution x resolution square pixels tile [-1, 1]^2, pixel
// (column, row) = index row * resolution + column, row 0 at the top (y = +1), column 0 on the left
// (x = -1). A pixel shows the sphere when its centre (x, y) has x^2 + y^2 < 1; the normal there is
// (x, y, sqrt(1 - x^2 - y^2)) and the direction to the camera is +z.
//
// Invariants: resolution >= 1 (std::invalid_argument otherwise); normal() is unit with z > 0 on the
// sphere; mask()[p] == 1 exactly when on_sphere(p).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::render {

// Pixels begin..end-1 (end excluded), in index order.
struct PixelRange {
  std::size_t begin = 0, end = 0;
};

class SphereView {
 public:
  explicit SphereView(std::size_t resolution);

  std::size_t resolution() const { return resolution_; }
  std::size_t pixels() const { return resolution_ * resolution_; }
  PixelRange all_pixels() const { return {0, pixels()}; }
  bool on_sphere(std::size_t pixel) const;
  // The sphere's normal under the pixel's centre; meaningful only on the sphere.
  Vector3 normal(std::size_t pixel) const;
  // The pixel's shading frame (Frame::from_z of the normal) and the direction to the camera in it.
  Frame local_frame(std::size_t pixel) const { return Frame::from_z(normal(pixel)); }
  Vector3 wo_local(std::size_t pixel) const { return local_frame(pixel).to_local(Vector3::UnitZ()); }
  std::vector<std::uint8_t> mask() const;

 private:
  double x_of(std::size_t pixel) const;
  double y_of(std::size_t pixel) const;
  std::size_t resolution_;
};

}  // namespace pbrfit::render
