#include "pbrfit/ltc/published_table.hpp"

#include <charconv>
#include <stdexcept>
#include <system_error>

namespace pbrfit::ltc {
namespace {

std::vector<double> numbers_of(std::string_view line, std::size_t line_number) {
  std::vector<double> values;
  while (!line.empty()) {
    const std::size_t comma = line.find(',');
    const std::string_view field = line.substr(0, comma);
    double value = 0.0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (error != std::errc() || end != field.data() + field.size())
      throw std::invalid_argument("line " + std::to_string(line_number) + ": '" + std::string(field) +
                                  "' is not a number");
    values.push_back(value);
    line = comma == std::string_view::npos ? std::string_view() : line.substr(comma + 1);
  }
  return values;
}

PublishedLtcCell cell_from(const std::vector<double>& v) {
  PublishedLtcCell cell;
  cell.roughness_index = static_cast<int>(v[0]);
  cell.view_index = static_cast<int>(v[1]);
  cell.ltc1 = {v[4], v[5], v[6], v[7]};
  cell.norm = v[8];
  cell.fresnel = v[9];
  cell.sphere = v[10];
  return cell;
}

}  // namespace

PublishedLtcTable::PublishedLtcTable(std::vector<PublishedLtcCell> cells, int size)
    : cells_(std::move(cells)), by_texel_(std::size_t(size * size), -1), size_(size) {
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const auto& c = cells_[i];
    if (c.roughness_index < 0 || c.roughness_index >= size || c.view_index < 0 || c.view_index >= size)
      throw std::invalid_argument("published LTC table: texel index out of range");
    by_texel_[std::size_t(c.roughness_index + c.view_index * size)] = int(i);
  }
}

const PublishedLtcCell* PublishedLtcTable::find(int roughness_index, int view_index) const {
  if (roughness_index < 0 || roughness_index >= size_ || view_index < 0 || view_index >= size_) return nullptr;
  const int index = by_texel_[std::size_t(roughness_index + view_index * size_)];
  return index < 0 ? nullptr : &cells_[std::size_t(index)];
}

PublishedLtcTable parse_published_ltc_table(std::string_view text) {
  std::vector<PublishedLtcCell> cells;
  std::size_t line_number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line[0] == '#' || line.starts_with("roughness_index")) continue;
    const auto values = numbers_of(line, line_number);
    if (values.size() != 11)
      throw std::invalid_argument("line " + std::to_string(line_number) + ": expected 11 numbers, got " +
                                  std::to_string(values.size()));
    cells.push_back(cell_from(values));
  }
  return PublishedLtcTable(std::move(cells));
}

}  // namespace pbrfit::ltc
