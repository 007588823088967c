#include "pbrfit/optimize/nelder_mead.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "free_dimensions.hpp"
#include "value_order.hpp"

namespace pbrfit::optimize {

// The starting simplex.
namespace {

// The signed offset along a free dimension d from x: step * width toward the upper bound if it fits,
// else toward the lower one, else all the way to the farther bound.
double axis_offset(const Bounds& bounds, std::size_t d, double x, double relative_step) {
  constexpr double smallest_step = 1e-12;
  const double offset = std::max(relative_step, smallest_step) * bounds.width(d);
  const double room_up = bounds.upper[d] - x;
  const double room_down = x - bounds.lower[d];
  double signed_offset = room_up >= room_down ? room_up : -room_down;
  if (offset <= room_up) {
    signed_offset = offset;
  } else if (offset <= room_down) {
    signed_offset = -offset;
  }
  if (x + signed_offset == x) signed_offset = room_up >= room_down ? room_up : -room_down;  // step too small
  return signed_offset;
}

}  // namespace

std::vector<std::vector<double>> starting_simplex(const Bounds& bounds, std::span<const double> start,
                                                  std::span<const double> relative_steps) {
  if (start.size() != bounds.dimension() || relative_steps.size() != bounds.dimension()) {
    throw std::invalid_argument("optimize: start point and steps must match the bounds' dimension");
  }
  std::vector<std::vector<double>> vertices{{start.begin(), start.end()}};
  clamp_into(bounds, vertices.front());
  for (std::size_t d = 0; d < bounds.dimension(); ++d) {
    if (bounds.is_fixed(d)) continue;
    if (!(relative_steps[d] > 0.0)) throw std::invalid_argument("optimize: simplex steps must be positive");
    vertices.push_back(vertices.front());
    const double moved = vertices.front()[d] + axis_offset(bounds, d, vertices.front()[d], relative_steps[d]);
    vertices.back()[d] = std::clamp(moved, bounds.lower[d], bounds.upper[d]);
  }
  return vertices;
}

// The working simplex and the moves on it.
namespace detail {

// The working simplex of a Nelder-Mead run: `count` vertices of `dimension` coordinates stored row by
// row, their values, and the vertex order by value.
//
// Invariants: points.size() == count * dimension; values and order have `count` entries; after sort(),
// order lists the vertices by increasing value, ties in vertex order.
struct Simplex {
  Simplex(std::size_t count, std::size_t dimension);

  std::span<double> row(std::size_t i) { return {points.data() + i * dimension, dimension}; }
  std::span<const double> row(std::size_t i) const { return {points.data() + i * dimension, dimension}; }
  std::size_t best() const { return order.front(); }
  std::size_t worst() const { return order.back(); }
  std::size_t second_worst() const { return order[order.size() - 2]; }

  void sort();
  // Largest |vertex - best vertex| / box width over the vertices and the free dimensions.
  double relative_size(const Bounds& bounds) const;
  double value_spread() const { return values[worst()] - values[best()]; }
  // The mean of every vertex but the worst, into `out`.
  void centroid_without_worst(std::span<double> out) const;

  std::size_t count;
  std::size_t dimension;
  std::vector<double> points;
  std::vector<double> values;
  std::vector<std::size_t> order;
};

Simplex::Simplex(std::size_t count, std::size_t dimension)
    : count(count),
      dimension(dimension),
      points(count * dimension, 0.0),
      values(count, std::numeric_limits<double>::infinity()),
      order(count) {
  std::iota(order.begin(), order.end(), std::size_t{0});
}

void Simplex::sort() { order_by_value(values, order); }

double Simplex::relative_size(const Bounds& bounds) const {
  const auto anchor = row(best());
  double size = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const auto vertex = row(i);
    for (std::size_t d = 0; d < dimension; ++d) {
      if (!bounds.is_fixed(d)) size = std::max(size, std::abs(vertex[d] - anchor[d]) / bounds.width(d));
    }
  }
  return size;
}

void Simplex::centroid_without_worst(std::span<double> out) const {
  std::fill(out.begin(), out.end(), 0.0);
  for (std::size_t k = 0; k + 1 < count; ++k) {
    const auto vertex = row(order[k]);
    for (std::size_t d = 0; d < dimension; ++d) out[d] += vertex[d];
  }
  const double share = 1.0 / static_cast<double>(count - 1);
  for (double& coordinate : out) coordinate *= share;
}

// The moves of Nelder-Mead on one working simplex, and the best point they have evaluated.
//
// Invariants: every evaluated point lies in the box; best() is the lowest value measured since the last
// build() or remeasure() started (earliest on ties; the earlier best while nothing has been measured
// since), and the simplex holds it unless the budget interrupted a step; a step whose budget runs out
// leaves the simplex consistent (only measured vertices moved).
class SimplexSearch {
 public:
  SimplexSearch(Evaluator& evaluator, const Bounds& bounds, const NelderMeadOptions& options);

  // A fresh simplex around `center` (starting_simplex above); false when the budget ran out first.
  bool build(std::span<const double> center, std::span<const double> relative_steps,
             std::optional<double> center_value);
  // Every vertex measured again at the current tolerance; false when the budget ran out first.
  bool remeasure();
  // One reflection / expansion / contraction / shrink step; false when the budget ran out during it.
  bool step();
  // Relative size <= x_tolerance and the values within the f tolerance (NelderMeadOptions).
  bool collapsed() const;

  const Simplex& simplex() const { return simplex_; }
  const Candidate& best() const { return best_; }

 private:
  bool measure(std::span<const double> x, double& value);
  bool try_point(double coefficient, std::vector<double>& point, double& value);
  void accept(const std::vector<double>& point, double value);
  bool shrink();

  Evaluator& evaluator_;
  const Bounds& bounds_;
  const NelderMeadOptions& options_;
  Simplex simplex_;
  std::vector<double> centroid_;
  std::vector<double> reflected_;
  std::vector<double> other_;  // the expanded or contracted point
  Candidate best_;
  bool best_is_stale_ = true;  // best_ predates the current simplex or tolerance: the next value replaces it
};

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

}  // namespace detail

// The run.
namespace {

class NelderMeadRun {
 public:
  NelderMeadRun(Evaluator& evaluator, const Bounds& bounds, const NelderMeadOptions& options)
      : evaluator_(evaluator), bounds_(bounds), options_(options), search_(evaluator, bounds, options),
        first_evaluation_(evaluator.used()) {}

  NelderMeadResult run(std::span<const double> start, std::optional<double> start_value);

 private:
  StopReason iterate_until_stop();
  bool restart();
  NelderMeadResult result(StopReason reason) const;

  Evaluator& evaluator_;
  const Bounds& bounds_;
  const NelderMeadOptions& options_;
  detail::SimplexSearch search_;
  std::size_t first_evaluation_;
  std::size_t iterations_ = 0;
  std::size_t restarts_ = 0;
  double value_at_last_restart_ = 0.0;
};

NelderMeadResult NelderMeadRun::run(std::span<const double> start, std::optional<double> start_value) {
  std::vector<double> steps = options_.relative_steps;
  if (steps.empty()) steps.assign(bounds_.dimension(), options_.initial_step);
  if (!search_.build(start, steps, start_value)) return result(StopReason::budget);
  return result(iterate_until_stop());
}

StopReason NelderMeadRun::iterate_until_stop() {
  for (;;) {
    if (search_.best().value <= options_.target) return StopReason::target;
    if (iterations_ >= options_.max_iterations) return StopReason::iteration_limit;
    // Values measured at a looser tolerance no longer compare with new ones.
    const bool tightened = evaluator_.follow_scale(search_.simplex().relative_size(bounds_));
    if (tightened && !search_.remeasure()) return StopReason::budget;
    if (search_.collapsed()) {
      if (!restart()) return evaluator_.exhausted() ? StopReason::budget : StopReason::converged;
      continue;  // the fresh simplex goes through the same checks (with no free dimension it is collapsed)
    }
    if (!search_.step()) return StopReason::budget;
    ++iterations_;
  }
}

// A fresh simplex around the best vertex, unless restarts are used up or the previous one did not pay.
bool NelderMeadRun::restart() {
  const detail::Simplex& simplex = search_.simplex();
  const double best = simplex.values[simplex.best()];
  const double gain_needed = std::max(options_.restart_gain_absolute, options_.restart_gain_relative * std::abs(best));
  const bool paid_off = restarts_ == 0 || value_at_last_restart_ - best > gain_needed;
  if (restarts_ >= options_.max_restarts || !paid_off) return false;
  value_at_last_restart_ = best;
  ++restarts_;
  const auto anchor = simplex.row(simplex.best());
  const std::vector<double> center(anchor.begin(), anchor.end());
  const std::vector<double> steps(bounds_.dimension(), options_.restart_step);
  return search_.build(center, steps, best);
}

NelderMeadResult NelderMeadRun::result(StopReason reason) const {
  NelderMeadResult result;
  result.best = search_.best();
  result.evaluations = evaluator_.used() - first_evaluation_;
  result.iterations = iterations_;
  result.restarts = restarts_;
  result.starts_run = result.evaluations > 0 ? 1 : 0;
  result.stop = reason;
  return result;
}

}  // namespace

NelderMeadResult nelder_mead(Evaluator& evaluator, const Bounds& bounds, std::span<const double> start,
                             const NelderMeadOptions& options, std::optional<double> start_value) {
  validate(bounds);
  if (!options.relative_steps.empty() && options.relative_steps.size() != bounds.dimension()) {
    throw std::invalid_argument("optimize: relative_steps must have one step per dimension");
  }
  return NelderMeadRun(evaluator, bounds, options).run(start, start_value);
}

NelderMeadResult nelder_mead(const Objective& objective, const Bounds& bounds, std::span<const double> start,
                             const NelderMeadOptions& options, std::size_t max_evaluations,
                             ToleranceSchedule schedule) {
  Evaluator evaluator(objective, max_evaluations, schedule);
  NelderMeadResult result = nelder_mead(evaluator, bounds, start, options);
  evaluator.finalize(result.best);
  result.evaluations = evaluator.used();
  return result;
}

}  // namespace pbrfit::optimize
