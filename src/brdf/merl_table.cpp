#include "pbrfit/brdf/merl_table.hpp"

#include <cmath>
#include <stdexcept>

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

std::array<double, 3> MerlTable::lookup(const ltc::Vector3& wi, const ltc::Vector3& wo) const {
  const std::size_t cell = merl_cell_of(to_half_diff(wi, wo)).flat();
  return {value(0, cell), value(1, cell), value(2, cell)};
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
