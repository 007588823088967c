// The running summary of a sweep (sweep_workload.hpp): cells done per level, and per model the best and
// worst error, the evaluations and how often the global search ran. Folded in any order: minima, maxima
// and integer counts.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "pbrfit/jobs/sweep/sweep_workload.hpp"

namespace pbrfit::jobs::sweep {
namespace {

constexpr std::size_t summary_models = SweepSummary::models;
constexpr std::size_t summary_levels = SweepSummary::levels;

void fold(SweepSummary::Model& s, const ModelFit& fit) {
  if (std::isfinite(fit.error)) {
    s.best = std::min(s.best, fit.error);
    s.worst = std::max(s.worst, fit.error);
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
  for (std::size_t m = 0; m < fits.size() && m < summary_models; ++m) fold(sum.model[m], fits[m]);
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
    char part[200];
    std::snprintf(part, sizeof part, "; %s error %.3g..%.3g, %.0f evaluations/cell, global search in %.0f%%",
                  models_[m].name.c_str(), s.best, s.worst, double(s.evaluations) / double(sum.cells),
                  100.0 * double(s.global_runs) / double(sum.cells));
    text += part;
    if (s.non_finite) text += ", " + std::to_string(s.non_finite) + " cells without a finite error";
  }
  return text;
}

}  // namespace pbrfit::jobs::sweep
