#include "pbrfit/brdf/merl_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pbrfit/brdf/rusinkiewicz.hpp"

namespace pbrfit::brdf {

MerlTable::MerlTable(std::vector<double> values) : values_(std::move(values)) {
  if (values_.size() != 3 * merl_cells) throw std::invalid_argument("MERL table: wrong number of values");
  for (double v : values_)
    if (!std::isnan(v) && !(std::isfinite(v) && v >= 0.0))
      throw std::invalid_argument("MERL table: a value is negative or infinite");
}

bool MerlTable::measured(std::size_t cell) const {
  return !std::isnan(value(0, cell)) && !std::isnan(value(1, cell)) && !std::isnan(value(2, cell));
}

std::size_t MerlTable::measured_cells() const {
  std::size_t count = 0;
  for (std::size_t c = 0; c < merl_cells; ++c) count += measured(c);
  return count;
}

std::array<double, 3> MerlTable::lookup(const Vector3& wi, const Vector3& wo) const {
  const std::size_t cell = merl_cell_of(to_half_diff(wi, wo)).flat();
  return {value(0, cell), value(1, cell), value(2, cell)};
}

namespace {

// The two cells around a position in cell units (cell i centred at i + 0.5), clamped into [0, count).
struct Neighbours {
  std::size_t lower, upper;
  double weight_upper;
};

Neighbours clamped_neighbours(double position, std::size_t count) {
  const double centred = position * double(count) - 0.5;
  if (!(centred > 0.0)) return {0, 0, 0.0};
  if (centred >= double(count - 1)) return {count - 1, count - 1, 0.0};
  const auto lower = static_cast<std::size_t>(centred);
  return {lower, lower + 1, centred - double(lower)};
}

Neighbours periodic_neighbours(double position, std::size_t count) {
  double centred = position * double(count) - 0.5;
  centred -= double(count) * std::floor(centred / double(count));
  const auto lower = std::min(static_cast<std::size_t>(centred), count - 1);
  return {lower, (lower + 1) % count, centred - double(lower)};
}

}  // namespace

std::array<double, 3> MerlTable::interpolate(const Vector3& wi, const Vector3& wo) const {
  const HalfDiff a = to_half_diff(wi, wo);
  constexpr double half_pi = 0.5 * std::numbers::pi;
  const Neighbours h = clamped_neighbours(std::sqrt(std::max(a.theta_h, 0.0) / half_pi), merl_theta_h);
  const Neighbours d = clamped_neighbours(a.theta_d / half_pi, merl_theta_d);
  const double phi_d = a.phi_d < 0.0 ? a.phi_d + 2.0 * half_pi : a.phi_d;  // reciprocity
  const Neighbours p = periodic_neighbours(phi_d / (2.0 * half_pi), merl_phi_d);
  std::array<double, 3> sum{};
  double weight_sum = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const bool uh = corner & 1, ud = corner & 2, up = corner & 4;
    const double weight = (uh ? h.weight_upper : 1.0 - h.weight_upper) * (ud ? d.weight_upper : 1.0 - d.weight_upper) *
                          (up ? p.weight_upper : 1.0 - p.weight_upper);
    if (weight == 0.0) continue;
    const MerlCell cell{uh ? h.upper : h.lower, ud ? d.upper : d.lower, up ? p.upper : p.lower};
    if (!measured(cell.flat())) continue;
    for (std::size_t c = 0; c < 3; ++c) sum[c] += weight * value(c, cell.flat());
    weight_sum += weight;
  }
  if (!(weight_sum > 0.0)) return {std::nan(""), std::nan(""), std::nan("")};
  for (double& v : sum) v /= weight_sum;
  return sum;
}

MerlTable merl_table_from_stored(const std::vector<double>& stored) {
  if (stored.size() != 3 * merl_cells) throw std::invalid_argument("MERL table: wrong number of stored values");
  std::vector<double> values(stored.size());
  for (std::size_t i = 0; i < stored.size(); ++i)
    values[i] = stored[i] < 0.0 ? std::nan("") : stored[i] * merl_channel_scale[i / merl_cells];
  return MerlTable(std::move(values));
}

std::vector<double> stored_from_merl_table(const MerlTable& table) {
  std::vector<double> stored(table.values().size());
  for (std::size_t i = 0; i < stored.size(); ++i) {
    const double v = table.values()[i];
    stored[i] = std::isnan(v) ? -1.0 : v / merl_channel_scale[i / merl_cells];
  }
  return stored;
}

}  // namespace pbrfit::brdf
