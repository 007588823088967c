#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "pbrfit/spec/schema.hpp"

namespace pbrfit::spec {
namespace {

// Levenshtein distance (insertions, deletions and substitutions cost 1), one row at a time.
std::size_t edit_distance(const std::string& from, const std::string& to) {
  std::vector<std::size_t> row(to.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= from.size(); ++i) {
    std::size_t diagonal = row[0];  // distance(from[0, i-1), to[0, j-1)) as j advances
    row[0] = i;
    for (std::size_t j = 1; j <= to.size(); ++j) {
      const std::size_t substitution = diagonal + (from[i - 1] == to[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[to.size()];
}

bool plausibly_meant(std::size_t distance, const std::string& word) {
  return distance < word.size() && (distance <= 2 || distance * 3 <= word.size());
}

}  // namespace

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = 0;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = edit_distance(word, candidate);
    if (!plausibly_meant(distance, word)) continue;
    if (best.empty() || distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace pbrfit::spec
