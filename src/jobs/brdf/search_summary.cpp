// The running summary of a genBRDF search (brdf_search_workload.hpp): generations evaluated, fits done,
// the best error and the smallest tree seen, then the materials evaluated. Folded in any order: counts,
// sums and minima.
#include <algorithm>
#include <cstdio>
#include <limits>

#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "search_records.hpp"

namespace pbrfit::jobs::brdf {

void BrdfSearchWorkload::fold_material(Summary& sum, const StageItem&, const MaterialEvaluation&) const { ++sum.materials; }

void BrdfSearchWorkload::fold_evaluation(Summary& sum, const StageItem& at, const EvaluationRecord& record) const {
  sum.evaluated += record.errors.size();
  sum.generation = std::max<std::uint64_t>(sum.generation, at.step + 1u);
  for (std::size_t k = 0; k < record.errors.size(); ++k)
    if (record.errors[k] < sum.best || (record.errors[k] == sum.best && record.sizes[k] < sum.best_size)) {
      sum.best = record.errors[k];
      sum.best_size = record.sizes[k];
    }
}

std::string BrdfSearchWorkload::headline_of(const Summary& sum) const {
  if (sum.evaluated == 0) return "no BRDF evaluated yet";
  char text[240];
  std::snprintf(text, sizeof text, "generation %llu of %zu, %llu BRDFs fitted; best error %.4g (tree of %.0f nodes)",
                static_cast<unsigned long long>(sum.generation), settings_.generations,
                static_cast<unsigned long long>(sum.evaluated), sum.best, sum.best_size);
  if (sum.materials == 0) return text;
  return std::string(text) + "; evaluation: " + std::to_string(sum.materials) + " of " +
         std::to_string(evaluated_materials()) + " materials";
}

double BrdfSearchWorkload::work_done_in(const Summary& sum) const {
  return double(sum.evaluated) * double(3 * settings_.data->materials());
}

}  // namespace pbrfit::jobs::brdf
