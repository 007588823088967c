#include "pbrfit/optimize/starting_simplex.hpp"

#include <algorithm>
#include <stdexcept>

namespace pbrfit::optimize {
namespace {

// The signed offset along a free dimension d from x: step * width toward the upper bound if it fits,
// else toward the lower one, else all the way to the farther bound.
double axis_offset(const Bounds& bounds, std::size_t d, double x, double relative_step) {
  constexpr double smallest_step = 1e-12;
  const double offset = std::max(relative_step, smallest_step) * bounds.width(d);
  const double room_up = bounds.upper[d] - x;
  const double room_down = x - bounds.lower[d];
  double signed_offset = room_up >= room_down ? room_up : -room_down;
  if (offset <= room_up) {
    signed_offset = offset;
  } else if (offset <= room_down) {
    signed_offset = -offset;
  }
  if (x + signed_offset == x) signed_offset = room_up >= room_down ? room_up : -room_down;  // step too small
  return signed_offset;
}

}  // namespace

std::vector<std::vector<double>> starting_simplex(const Bounds& bounds, std::span<const double> start,
                                                  std::span<const double> relative_steps) {
  if (start.size() != bounds.dimension() || relative_steps.size() != bounds.dimension()) {
    throw std::invalid_argument("optimize: start point and steps must match the bounds' dimension");
  }
  std::vector<std::vector<double>> vertices{{start.begin(), start.end()}};
  clamp_into(bounds, vertices.front());
  for (std::size_t d = 0; d < bounds.dimension(); ++d) {
    if (bounds.is_fixed(d)) continue;
    if (!(relative_steps[d] > 0.0)) throw std::invalid_argument("optimize: simplex steps must be positive");
    vertices.push_back(vertices.front());
    const double moved = vertices.front()[d] + axis_offset(bounds, d, vertices.front()[d], relative_steps[d]);
    vertices.back()[d] = std::clamp(moved, bounds.lower[d], bounds.upper[d]);
  }
  return vertices;
}

}  // namespace pbrfit::optimize
