#pragma once
// The tabulated view directions of an eBRDF table, in the geometric frame (z = the geometric normal):
// n_theta elevations theta_i = 0.999 * pi / 2 * sin(i / (n_theta - 1) * pi / 2) from 0 to just above the
// horizon (0.1 when n_theta = 1), and n_phi azimuths phi_j = 2 pi j / n_phi over the whole circle (the
// thesis repeats 0 as 2 pi; here each azimuth is distinct and the table wraps).
// The thesis (Nahmias 2022, section 3.4.1) spaces the elevations evenly; here they crowd towards grazing,
// where a sharp lobe changes fastest (it is pressed against the horizon and leaves the mirror direction):
// with 8 elevations the last interval is 87.6 to 89.9 degrees instead of 77.1 to 89.9, which halves the
// error of a flat map's renders at grazing views (docs/BENCHMARKS.md, eBRDF fidelity).
//
// Invariants: view index = i * n_phi + j; direction() is a unit vector with z > 0.
#include <cstddef>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ebrdf {

struct ViewGrid {
  std::size_t n_theta = 8;
  std::size_t n_phi = 16;

  std::size_t count() const { return n_theta * n_phi; }
  double theta(std::size_t i) const;
  // The continuous elevation index of theta (theta(i) -> i), clamped to [0, n_theta - 1].
  double theta_position(double theta) const;
  double phi(std::size_t j) const;
  Vector3 direction(std::size_t view) const;
};

// w rotated about z by -phi: the frame in which a view of azimuth phi has azimuth 0.
Vector3 rotate_azimuth_to_zero(const Vector3& w, double phi);

}  // namespace pbrfit::ebrdf
