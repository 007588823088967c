#include "pbrfit/render/pruned_light_table.hpp"

#include <algorithm>
#include <stdexcept>

namespace pbrfit::render {
namespace {

using brdf::merl_cells;

struct Scored {
  double score = 0.0;
  std::uint32_t cell = 0;
};

double share(double weight, double total) { return total > 0.0 ? weight / total : 0.0; }

// Lit cells, heaviest first (ties by flat index).
std::vector<Scored> heaviest_first(const LightWeightTable& table) {
  const Rgb total = table.total();
  std::vector<Scored> cells;
  for (std::size_t c = 0; c < merl_cells; ++c) {
    double score = 0.0;
    for (std::size_t k = 0; k < 3; ++k) score += share(table.weight(k, c), total[k]);
    if (score > 0.0) cells.push_back({score, std::uint32_t(c)});
  }
  std::sort(cells.begin(), cells.end(),
            [](const Scored& a, const Scored& b) { return a.score != b.score ? a.score > b.score : a.cell < b.cell; });
  return cells;
}

bool reached(const Rgb& kept, const Rgb& total, double keep_share) {
  for (std::size_t k = 0; k < 3; ++k)
    if (kept[k] < keep_share * total[k]) return false;
  return true;
}

}  // namespace

PrunedLightTable::PrunedLightTable(const LightWeightTable& table, double keep_share) {
  if (!(keep_share > 0.0 && keep_share <= 1.0)) throw std::invalid_argument("keep_share must be in (0, 1]");
  const std::vector<Scored> order = heaviest_first(table);
  const Rgb total = table.total();
  Rgb kept = {0.0, 0.0, 0.0}, dropped = {0.0, 0.0, 0.0};
  for (const Scored& s : order) {
    const bool keep = !reached(kept, total, keep_share);
    if (keep) cells_.push_back(s.cell);
    for (std::size_t k = 0; k < 3; ++k) (keep ? kept : dropped)[k] += table.weight(k, s.cell);
  }
  std::sort(cells_.begin(), cells_.end());
  weights_.resize(3 * size());
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t i = 0; i < size(); ++i) weights_[k * size() + i] = table.weight(k, cells_[i]);
  squared_.resize(weights_.size());
  std::transform(weights_.begin(), weights_.end(), squared_.begin(), [](double w) { return w * w; });
  for (std::size_t k = 0; k < 3; ++k) dropped_share_[k] = share(dropped[k], total[k]);
}

std::vector<brdf::DirectionPair> representative_pairs(const PrunedLightTable& table) {
  std::vector<brdf::DirectionPair> pairs;
  pairs.reserve(table.size());
  for (std::uint32_t cell : table.cells()) pairs.push_back(brdf::from_half_diff(brdf::merl_centre_of(brdf::merl_cell_at(cell))));
  return pairs;
}

}  // namespace pbrfit::render
