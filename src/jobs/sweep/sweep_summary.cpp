// The running summary of a sweep (sweep_workload.hpp): cells done per level, and per model the best and
// worst error, the errors' distribution, the evaluations and how often the global search ran. Folded in any
// order: minima, maxima and integer counts. The headline gives errors as percentiles over the cells (half
// the cells and 95 % of them at most a bound), not as a range that a few degenerate cells can stretch over
// dozens of orders of magnitude; for a model with a headline output (LTC tables: the L2 error relative to
// the target's own L2 norm) that output, in per cent, instead of the fitting objective.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "pbrfit/jobs/sweep/sweep_workload.hpp"

namespace pbrfit::jobs::sweep {
namespace {

constexpr std::size_t summary_models = SweepSummary::models;
constexpr std::size_t summary_levels = SweepSummary::levels;

std::size_t error_bin(double error) {
  if (!(error > 0.0)) return 0;
  const double position = std::floor((std::log10(error) - SweepSummary::lowest_decade) * SweepSummary::bins_per_decade);
  return std::size_t(std::clamp(position, 0.0, double(SweepSummary::error_bins - 1)));
}

// The upper edge of bin `bin`: every error counted in it is at most this.
double bin_upper_edge(std::size_t bin) {
  return std::pow(10.0, SweepSummary::lowest_decade + double(bin + 1) / SweepSummary::bins_per_decade);
}

// A bound that at least `fraction` of the model's finite errors do not exceed: the upper edge of the bin
// where the count reaches that fraction (the worst error in the last bin, which has no upper edge).
double error_bound(const SweepSummary::Model& s, double fraction) {
  std::uint64_t total = 0;
  for (const auto count : s.error_counts) total += count;
  const auto needed = std::uint64_t(std::ceil(fraction * double(total)));
  std::uint64_t seen = 0;
  for (std::size_t bin = 0; bin < SweepSummary::error_bins; ++bin) {
    seen += s.error_counts[bin];
    if (seen >= needed && seen > 0)
      return bin + 1 == SweepSummary::error_bins ? s.worst : std::min(bin_upper_edge(bin), s.worst);
  }
  return s.worst;
}

// `summarized` is the fit's error or the model's headline output (ModelInfo::headline_output).
void fold(SweepSummary::Model& s, const ModelFit& fit, double summarized) {
  if (std::isfinite(summarized)) {
    s.best = std::min(s.best, summarized);
    s.worst = std::max(s.worst, summarized);
    ++s.error_counts[error_bin(summarized)];
  } else {
    ++s.non_finite;
  }
  s.evaluations += fit.evaluations;
  s.global_runs += fit.global_ran;
}

}  // namespace

// The summary starts value-initialized: best errors at +inf.
void SweepWorkload::fold_cell(Summary& sum, const StageItem& at, const CellFits& fits) const {
  ++sum.cells;
  ++sum.level_cells[std::min<std::size_t>(schedule_.cell_of(at.step, at.item()).level, summary_levels - 1)];
  for (std::size_t m = 0; m < fits.size() && m < summary_models; ++m) {
    const auto offset = models_[m].headline_offset();
    fold(sum.model[m], fits[m], offset ? fits[m].outputs.at(*offset) : fits[m].error);
  }
}

std::string SweepWorkload::headline_of(const Summary& sum) const {
  if (sum.cells == 0) return "no cells fitted yet";
  const auto& levels = schedule_.levels();
  std::size_t level = 0;
  for (std::size_t l = 0; l < levels.size() && l < summary_levels; ++l)
    if (sum.level_cells[l] > 0) level = l;
  std::string text = "level " + std::to_string(level + 1) + "/" + std::to_string(levels.size()) + ": " +
                     std::to_string(sum.level_cells[level]) + "/" + std::to_string(levels[level].cell_count()) +
                     " cells";
  for (std::size_t m = 0; m < models_.size() && m < summary_models; ++m) {
    const SweepSummary::Model& s = sum.model[m];
    char part[320];
    const bool relative = !models_[m].headline_output.empty();
    const std::string what = models_[m].name + " " + (relative ? models_[m].headline_label : "error");
    if (s.non_finite < sum.cells && relative)
      std::snprintf(part, sizeof part, "; %s: half the cells <= %.3g%%, 95%% <= %.3g%%", what.c_str(),
                    100.0 * error_bound(s, 0.5), 100.0 * error_bound(s, 0.95));
    else if (s.non_finite < sum.cells)
      std::snprintf(part, sizeof part, "; %s: half the cells <= %.3g, 95%% <= %.3g", what.c_str(),
                    error_bound(s, 0.5), error_bound(s, 0.95));
    else
      std::snprintf(part, sizeof part, "; %s: none finite", what.c_str());
    text += part;
    std::snprintf(part, sizeof part, ", %.0f evaluations/cell, global search in %.0f%%",
                  double(s.evaluations) / double(sum.cells), 100.0 * double(s.global_runs) / double(sum.cells));
    text += part;
    if (s.non_finite) text += ", " + std::to_string(s.non_finite) + " cells without a finite error";
  }
  return text;
}

}  // namespace pbrfit::jobs::sweep
