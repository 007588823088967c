#include "search_records.hpp"

#include <algorithm>
#include <cmath>

namespace pbrfit::jobs::brdf {
namespace {

double median(std::span<const double> values) {
  if (values.empty()) return 0.0;
  std::vector<double> sorted(values.begin(), values.end());
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
  return sorted[sorted.size() / 2];
}

}  // namespace

IslandStatistics island_statistics(std::span<const double> errors, std::span<const double> sizes,
                                   std::span<const std::uint8_t> abandoned) {
  IslandStatistics out;
  for (std::size_t k = 0; k < errors.size(); ++k) {
    if (!std::isfinite(errors[k])) ++out.infeasible;
    else if (abandoned[k]) ++out.abandoned;
    else out.best_error = std::min(out.best_error, errors[k]);
  }
  out.median_error = errors.empty() ? gp::worst_error : median(errors);
  out.median_size = median(sizes);
  return out;
}

}  // namespace pbrfit::jobs::brdf
