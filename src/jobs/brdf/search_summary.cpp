// The running summary of a genBRDF search (brdf_search_workload.hpp): generations evaluated, fits done,
// the best error and the smallest tree seen, then the materials evaluated. Folded in any order: counts,
// sums and minima.
#include <algorithm>
#include <cstdio>
#include <limits>

#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "search_records.hpp"

namespace pbrfit::jobs::brdf {
namespace {

struct Summary {
  std::uint64_t evaluated = 0;   // genomes
  std::uint64_t generation = 0;  // highest generation evaluated, plus one
  double best = std::numeric_limits<double>::infinity();
  double best_size = 0.0;
  std::uint64_t materials = 0;  // evaluated after the search
};

}  // namespace

void BrdfSearchWorkload::fold_summary(Bytes& summary, WorkItemId id, const Bytes& result) const {
  if (role(id) != Role::evaluation && role(id) != Role::material) return;
  auto sum = runtime::summary_as<Summary>(summary);
  if (role(id) == Role::material) {
    ++sum.materials;
    runtime::store_summary(summary, sum);
    return;
  }
  const auto record = decode_evaluation(result);
  sum.evaluated += record.errors.size();
  sum.generation = std::max<std::uint64_t>(sum.generation, generation_of(id.stage) + 1u);
  for (std::size_t k = 0; k < record.errors.size(); ++k)
    if (record.errors[k] < sum.best || (record.errors[k] == sum.best && record.sizes[k] < sum.best_size)) {
      sum.best = record.errors[k];
      sum.best_size = record.sizes[k];
    }
  runtime::store_summary(summary, sum);
}

std::string BrdfSearchWorkload::headline(const Bytes& summary) const {
  const auto sum = runtime::summary_as<Summary>(summary);
  if (sum.evaluated == 0) return "no BRDF evaluated yet";
  char text[240];
  std::snprintf(text, sizeof text, "generation %llu of %zu, %llu BRDFs fitted; best error %.4g (tree of %.0f nodes)",
                static_cast<unsigned long long>(sum.generation), settings_.generations,
                static_cast<unsigned long long>(sum.evaluated), sum.best, sum.best_size);
  if (sum.materials == 0) return text;
  return std::string(text) + "; evaluation: " + std::to_string(sum.materials) + " of " +
         std::to_string(evaluated_materials()) + " materials";
}

double BrdfSearchWorkload::work_done(const Bytes& summary) const {
  return double(runtime::summary_as<Summary>(summary).evaluated) * double(3 * settings_.data->materials());
}

}  // namespace pbrfit::jobs::brdf
