#pragma once
// Test support: reads the published GGX LTC table, data/reference/ltc_ggx_heitz2016_64.csv (columns and
// provenance in data/reference/README.md). Lines starting with '#' and the column-name line are skipped;
// every other line must hold 11 comma-separated numbers. Throws std::runtime_error on anything else.
#include <array>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace pbrfit::test {

struct PublishedLtcCell {
  int roughness_index = 0;
  int view_index = 0;
  std::array<double, 4> ltc1{};  // the shader form of the inverse matrix
  double norm = 0.0;
  double fresnel = 0.0;
  double sphere = 0.0;
};

inline std::vector<PublishedLtcCell> read_published_ltc_table(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot open " + path);
  std::vector<PublishedLtcCell> cells;
  std::string line;
  while (std::getline(file, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("roughness_index", 0) == 0) continue;
    std::vector<double> values;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) values.push_back(std::stod(field));
    if (values.size() != 11) throw std::runtime_error("malformed row: " + line);
    PublishedLtcCell cell;
    cell.roughness_index = static_cast<int>(values[0]);
    cell.view_index = static_cast<int>(values[1]);
    cell.ltc1 = {values[4], values[5], values[6], values[7]};
    cell.norm = values[8];
    cell.fresnel = values[9];
    cell.sphere = values[10];
    cells.push_back(cell);
  }
  return cells;
}

#ifdef PBRFIT_SOURCE_DIR
inline std::string published_ltc_table_path() {
  return std::string(PBRFIT_SOURCE_DIR) + "/data/reference/ltc_ggx_heitz2016_64.csv";
}
#endif

}  // namespace pbrfit::test
