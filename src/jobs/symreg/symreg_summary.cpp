// The running summary of a symbolic-regression job (symreg_workload.hpp), in the style of PySR's progress
// lines: the generation reached, the evaluations spent, and per output the best error found at each cost.
// Folded in any order: sums, maxima and per-cost minima.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "pbrfit/jobs/symreg/symreg_workload.hpp"

namespace pbrfit::jobs::symreg {
namespace {

constexpr std::size_t summary_outputs = SymregSummary::outputs;
constexpr std::size_t cost_buckets = SymregSummary::cost_buckets;

std::size_t bucket_of(double cost) { return std::min<std::size_t>(std::size_t(std::max(std::lround(cost), 0L)), cost_buckets - 1); }

}  // namespace

void SymregWorkload::fold_epoch(Summary& sum, const StageItem& at, const EpochResult& result) const {
  const std::size_t o = output_of(at.item());
  const EpochRecord epoch = epoch_record(result, input_count(o));
  sum.evaluations += epoch.evaluations;
  sum.generation = std::max(sum.generation, epoch.generation);
  if (o < summary_outputs) {
    for (const auto& entry : epoch.front) {
      const std::size_t b = bucket_of(entry.fitness.cost);
      const bool has = (sum.seen[o] >> b) & 1u;
      if (!has || entry.fitness.error < sum.best[o][b]) sum.best[o][b] = entry.fitness.error;
      sum.seen[o] |= std::uint64_t(1) << b;
    }
  }
}

std::string SymregWorkload::headline_of(const Summary& sum) const {
  if (sum.evaluations == 0) return "no generations yet";
  char text[160];
  std::snprintf(text, sizeof text, "generation %llu, %.3g evaluations", static_cast<unsigned long long>(sum.generation),
                double(sum.evaluations));
  std::string line = text;
  for (std::size_t o = 0; o < settings_.data->outputs.size() && o < summary_outputs; ++o) {
    line += "; " + settings_.data->outputs[o].name + " best error by cost";
    std::vector<std::string> front;  // the costs where the error improves; the last 8 are shown
    double previous = HUGE_VAL;
    for (std::size_t b = 0; b < cost_buckets; ++b) {
      if (!((sum.seen[o] >> b) & 1u) || !(sum.best[o][b] < previous)) continue;
      previous = sum.best[o][b];
      std::snprintf(text, sizeof text, " %zu: %.3g", b, previous);
      front.push_back(text);
    }
    for (std::size_t k = front.size() > 8 ? front.size() - 8 : 0; k < front.size(); ++k) line += front[k];
  }
  return line;
}

}  // namespace pbrfit::jobs::symreg
