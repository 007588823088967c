#pragma once
// The published 64 x 64 GGX LTC table of Heitz et al. 2016 (data/reference/ltc_ggx_heitz2016_64.csv,
// columns and provenance in data/reference/README.md), parsed from the CSV's text. Lines starting with
// '#', empty lines and the column-name line are skipped; every other line must hold 11 comma-separated
// numbers: roughness_index, view_index, roughness, sqrt_one_minus_cos, ltc_1 (4), norm, fresnel, sphere.
//
// Contract: parse_published_ltc_table throws std::invalid_argument naming the 1-based line of the first
// malformed row; cells keep the file's order; find() is nullptr for a texel the table does not hold.
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace pbrfit::ltc {

struct PublishedLtcCell {
  int roughness_index = 0;
  int view_index = 0;
  std::array<double, 4> ltc1{};  // the shader form of the inverse matrix (shader_form.hpp)
  double norm = 0.0;
  double fresnel = 0.0;
  double sphere = 0.0;
};

class PublishedLtcTable {
 public:
  PublishedLtcTable() = default;
  explicit PublishedLtcTable(std::vector<PublishedLtcCell> cells, int size = 64);

  const std::vector<PublishedLtcCell>& cells() const { return cells_; }
  int size() const { return size_; }
  const PublishedLtcCell* find(int roughness_index, int view_index) const;

 private:
  std::vector<PublishedLtcCell> cells_;
  std::vector<int> by_texel_;  // index into cells_ of texel a + t * size, or -1
  int size_ = 64;
};

PublishedLtcTable parse_published_ltc_table(std::string_view csv_text);

}  // namespace pbrfit::ltc
