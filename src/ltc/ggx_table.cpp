#include "pbrfit/ltc/ggx_table.hpp"

#include <algorithm>
#include <cmath>

#include "pbrfit/ltc/sphere_form_factor.hpp"

namespace pbrfit::ltc {
namespace {

double axis_value(int index, int size) { return static_cast<double>(index) / static_cast<double>(size - 1); }

}  // namespace

std::size_t GgxTableLayout::flat_index(const TableCell& cell) const {
  return static_cast<std::size_t>(cell.roughness_index) +
         static_cast<std::size_t>(cell.view_index) * static_cast<std::size_t>(size);
}

double GgxTableLayout::roughness(const TableCell& cell) const { return axis_value(cell.roughness_index, size); }

double GgxTableLayout::alpha(const TableCell& cell) const {
  const double r = roughness(cell);
  return std::max(r * r, min_alpha);
}

double GgxTableLayout::sqrt_one_minus_cos(const TableCell& cell) const { return axis_value(cell.view_index, size); }

double GgxTableLayout::cos_theta_view(const TableCell& cell) const {
  const double x = sqrt_one_minus_cos(cell);
  const double cosine = 1.0 - x * x;
  const double theta = std::acos(std::clamp(cosine, -1.0, 1.0));
  return theta <= max_theta ? cosine : std::cos(max_theta);
}

double GgxTableLayout::sphere_term(const TableCell& cell) const {
  const double z = 2.0 * axis_value(cell.roughness_index, size) - 1.0;
  return sphere_form_factor_ratio(z, axis_value(cell.view_index, size));
}

std::vector<MarchingStep> marching_order(const GgxTableLayout& layout) {
  std::vector<MarchingStep> order;
  order.reserve(static_cast<std::size_t>(layout.size) * static_cast<std::size_t>(layout.size));
  for (int a = layout.size - 1; a >= 0; --a) {
    for (int t = 0; t < layout.size; ++t) {
      MarchingStep step{{a, t}, std::nullopt};
      if (t > 0) {
        step.predecessor = TableCell{a, t - 1};
      } else if (a < layout.size - 1) {
        step.predecessor = TableCell{a + 1, 0};
      }
      order.push_back(step);
    }
  }
  return order;
}

}  // namespace pbrfit::ltc
