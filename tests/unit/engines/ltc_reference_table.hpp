#pragma once
// Test support: reads the published GGX LTC table, data/reference/ltc_ggx_heitz2016_64.csv, with the
// engine's parser (ltc/published_table.hpp). Throws std::runtime_error when the file cannot be read.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pbrfit/ltc/published_table.hpp"

namespace pbrfit::test {

using PublishedLtcCell = ltc::PublishedLtcCell;

inline std::vector<PublishedLtcCell> read_published_ltc_table(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot open " + path);
  std::stringstream text;
  text << file.rdbuf();
  return ltc::parse_published_ltc_table(text.str()).cells();
}

#ifdef PBRFIT_SOURCE_DIR
inline std::string published_ltc_table_path() {
  return std::string(PBRFIT_SOURCE_DIR) + "/data/reference/ltc_ggx_heitz2016_64.csv";
}
#endif

}  // namespace pbrfit::test
