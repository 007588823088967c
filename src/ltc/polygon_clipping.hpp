#pragma once
// Internal: the clamped-cosine integral over a planar polygon clipped to z >= 0, with the clipping done on
// the fly (Sutherland-Hodgman against the plane z = 0, which contains the origin, so clipping the planar
// polygon clips its spherical projection along the horizon) and no storage for the clipped polygon.
#include <cmath>
#include <cstddef>
#include <numbers>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc::detail {

// theta * normalize(a x b) for unit a, b: the edge term of Lambert's formula (vector form), written with
// atan2 so that short edges keep their accuracy.
inline Vector3 edge_form_factor(const Vector3& a, const Vector3& b) {
  const Vector3 normal = a.cross(b);
  const double sine = normal.norm();
  const double angle = std::atan2(sine, a.dot(b));
  return sine > 1e-12 ? Vector3(normal * (angle / sine)) : normal;
}

// Sums the z edge terms along the vertices it is given, closing the loop on close().
class BoundarySum {
 public:
  void add(const Vector3& point) {
    const Vector3 direction = point.normalized();
    if (count_++ == 0) {
      first_ = direction;
    } else {
      sum_ += edge_form_factor(last_, direction).z();
    }
    last_ = direction;
  }
  double close() const { return count_ >= 2 ? sum_ + edge_form_factor(last_, first_).z() : 0.0; }

 private:
  Vector3 first_;
  Vector3 last_;
  double sum_ = 0.0;
  int count_ = 0;
};

inline Vector3 horizon_crossing(const Vector3& from, const Vector3& to) {
  return from + (to - from) * (from.z() / (from.z() - to.z()));
}

// vertex_at(i) returns vertex i (i < count) of the polygon as a point; count >= 3.
template <class VertexAt>
double clipped_clamped_cosine_integral(std::size_t count, const VertexAt& vertex_at) {
  BoundarySum boundary;
  Vector3 previous = vertex_at(count - 1);
  for (std::size_t i = 0; i < count; ++i) {
    const Vector3 current = vertex_at(i);
    const bool previous_above = previous.z() >= 0.0;
    const bool current_above = current.z() >= 0.0;
    if (previous_above != current_above) boundary.add(horizon_crossing(previous, current));
    if (current_above) boundary.add(current);
    previous = current;
  }
  return std::abs(boundary.close()) * (0.5 * std::numbers::inv_pi);
}

}  // namespace pbrfit::ltc::detail
