#include "simplex_search.hpp"

#include <algorithm>
#include <cmath>

#include "free_dimensions.hpp"
#include "pbrfit/optimize/starting_simplex.hpp"

namespace pbrfit::optimize::detail {

SimplexSearch::SimplexSearch(Evaluator& evaluator, const Bounds& bounds, const NelderMeadOptions& options)
    : evaluator_(evaluator),
      bounds_(bounds),
      options_(options),
      simplex_(free_dimensions(bounds).size() + 1, bounds.dimension()),
      centroid_(bounds.dimension()),
      reflected_(bounds.dimension()),
      other_(bounds.dimension()) {}

bool SimplexSearch::build(std::span<const double> center, std::span<const double> relative_steps,
                          std::optional<double> center_value) {
  const auto vertices = starting_simplex(bounds_, center, relative_steps);
  best_is_stale_ = true;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    std::copy(vertices[i].begin(), vertices[i].end(), simplex_.row(i).begin());
    if (i == 0 && center_value) {
      simplex_.values[0] = *center_value;
      best_ = Candidate{vertices[0], *center_value, evaluator_.tolerance()};
      best_is_stale_ = false;
    } else if (!measure(simplex_.row(i), simplex_.values[i])) {
      return false;
    }
  }
  simplex_.sort();
  return true;
}

bool SimplexSearch::remeasure() {
  best_is_stale_ = true;
  for (std::size_t i = 0; i < simplex_.count; ++i) {
    if (!measure(simplex_.row(i), simplex_.values[i])) return false;
  }
  simplex_.sort();
  return true;
}

bool SimplexSearch::collapsed() const {
  const double best = simplex_.values[simplex_.best()];
  const double worst = simplex_.values[simplex_.worst()];
  const double f_tolerance = std::max(options_.f_tolerance_absolute, options_.f_tolerance_relative * std::abs(best));
  const bool flat = worst - best <= f_tolerance || worst == best;  // equal infinities are flat too
  return flat && simplex_.relative_size(bounds_) <= options_.x_tolerance;
}

// Evaluates x and keeps it as the best if it is; false (nothing evaluated) when the budget is spent.
bool SimplexSearch::measure(std::span<const double> x, double& value) {
  if (evaluator_.exhausted()) return false;
  value = evaluator_.measure(x);
  if (best_is_stale_ || value < best_.value) {
    best_.x.assign(x.begin(), x.end());  // reuses the buffer: no allocation per evaluation
    best_.value = value;
    best_.tolerance = evaluator_.tolerance();
    best_is_stale_ = false;
  }
  return true;
}

// point = clamp(centroid + coefficient (centroid - worst)), then measured.
bool SimplexSearch::try_point(double coefficient, std::vector<double>& point, double& value) {
  const auto worst = simplex_.row(simplex_.worst());
  for (std::size_t d = 0; d < bounds_.dimension(); ++d) {
    const double moved = centroid_[d] + coefficient * (centroid_[d] - worst[d]);
    point[d] = std::clamp(moved, bounds_.lower[d], bounds_.upper[d]);
  }
  return measure(point, value);
}

void SimplexSearch::accept(const std::vector<double>& point, double value) {
  const std::size_t worst = simplex_.worst();
  std::copy(point.begin(), point.end(), simplex_.row(worst).begin());
  simplex_.values[worst] = value;
  simplex_.sort();
}

bool SimplexSearch::step() {
  simplex_.centroid_without_worst(centroid_);
  const double best = simplex_.values[simplex_.best()];
  const double worst = simplex_.values[simplex_.worst()];
  double reflected = 0.0;
  double other = 0.0;
  if (!try_point(options_.reflection, reflected_, reflected)) return false;
  if (reflected < best) {
    const bool measured = try_point(options_.expansion, other_, other);
    const bool expand = measured && other < reflected;
    accept(expand ? other_ : reflected_, expand ? other : reflected);
    return measured;
  }
  if (reflected < simplex_.values[simplex_.second_worst()]) {
    accept(reflected_, reflected);
    return true;
  }
  const bool outside = reflected < worst;
  const double coefficient = outside ? options_.contraction * options_.reflection : -options_.contraction;
  if (!try_point(coefficient, other_, other)) return false;
  if (outside ? other <= reflected : other < worst) {
    accept(other_, other);
    return true;
  }
  return shrink();
}

// Every vertex but the best moves toward the best by the shrink coefficient; a vertex moves only once
// it has been measured.
bool SimplexSearch::shrink() {
  const std::size_t best = simplex_.best();
  const auto anchor = simplex_.row(best);
  for (std::size_t i = 0; i < simplex_.count; ++i) {
    if (i == best) continue;
    const auto vertex = simplex_.row(i);
    for (std::size_t d = 0; d < bounds_.dimension(); ++d) {
      other_[d] = anchor[d] + options_.shrink * (vertex[d] - anchor[d]);
    }
    if (!measure(other_, simplex_.values[i])) return false;
    std::copy(other_.begin(), other_.end(), vertex.begin());
  }
  simplex_.sort();
  return true;
}

}  // namespace pbrfit::optimize::detail
