// The evaluation stages of a genBRDF search (brdf_search_workload.hpp; Brady et al., section 4): the seed,
// the named references and the chosen front members fitted to every training and testing material and
// rendered, then the errors averaged per material set.
#include <algorithm>
#include <cmath>

#include "pbrfit/jobs/brdf/brdf_inputs.hpp"
#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "front_knee.hpp"
#include "search_records.hpp"

namespace pbrfit::jobs::brdf {
namespace {

const ScoredTree& most_accurate(const std::vector<ScoredTree>& trees) {
  return *std::min_element(trees.begin(), trees.end(), [](const auto& a, const auto& b) { return a.error < b.error; });
}

// The most accurate member no larger than max_size; the smallest when none is (the front is by size).
const ScoredTree& comparable(const std::vector<ScoredTree>& front, double max_size) {
  std::vector<ScoredTree> small;
  for (const auto& f : front)
    if (f.size() <= max_size) small.push_back(f);
  if (small.empty()) return front.front();
  const auto& best = most_accurate(small);
  for (const auto& f : front)
    if (f.tree == best.tree) return f;
  return front.front();
}

const ScoredTree& knee(const FrontRecord& record) {
  if (!record.simplified.empty()) return record.simplified.back();
  return record.front[front_knee(record.front)];
}

double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  return values.empty() ? std::nan("") : sum / double(values.size());
}

double reduction(double value, double baseline) { return 100.0 * (1.0 - value / baseline); }

}  // namespace

std::vector<std::string> BrdfSearchWorkload::model_names() const {
  std::vector<std::string> names = {settings_.seed_name};
  for (const auto& r : settings_.evaluation.references) names.push_back(r.name);
  for (const auto member : settings_.evaluation.members) names.emplace_back(member_name(member));
  return names;
}

std::vector<ScoredTree> BrdfSearchWorkload::evaluated_models(const FrontRecord& record) const {
  std::vector<ScoredTree> models = {{settings_.seed, gp::worst_error, 0}};
  for (const auto& r : settings_.evaluation.references) models.push_back({r.tree, gp::worst_error, 0});
  for (const auto member : settings_.evaluation.members) {
    if (record.front.empty()) {
      models.push_back(models.front());
      continue;
    }
    const double max_size = settings_.evaluation.comparable_size * double(settings_.seed.size());
    switch (member) {
      case EvaluatedMember::comparable: models.push_back(comparable(record.front, max_size)); break;
      case EvaluatedMember::knee: models.push_back(knee(record)); break;
      case EvaluatedMember::best: models.push_back(most_accurate(record.front)); break;
    }
  }
  return models;
}

std::vector<gp::SyntaxTree> BrdfSearchWorkload::material_input(std::uint32_t, std::uint64_t, const Kept& kept) const {
  std::vector<gp::SyntaxTree> trees;
  for (auto& m : evaluated_models(kept.at<FrontRecord>("last front", 0, 0))) trees.push_back(std::move(m.tree));
  return trees;
}

std::string BrdfSearchWorkload::evaluated_material(std::uint64_t item) const {
  const auto& e = settings_.evaluation;
  return item < e.training.size() ? e.training[item] : e.testing[item - e.training.size()];
}

MaterialEvaluation BrdfSearchWorkload::evaluate_material(const Task<Nothing, std::vector<gp::SyntaxTree>>& task) const {
  const std::string name = evaluated_material(task.item());
  const auto material = load_material(name, settings_.evaluation.source);
  if (task.stop_requested()) throw runtime::Cancelled();
  return evaluate_on_material(*settings_.scene, *settings_.evaluation.scene, material, name, task.input,
                              settings_.evaluation.fit, settings_.evaluation.exposure, task.random(0));
}

std::vector<MaterialEvaluation> BrdfSearchWorkload::averages_input(std::uint32_t, std::uint64_t, const Kept& kept) const {
  std::vector<MaterialEvaluation> materials;
  for (std::uint64_t m = 0; m < evaluated_materials(); ++m) materials.push_back(kept.at<MaterialEvaluation>("materials", 0, m));
  return materials;
}

std::vector<AverageRow> BrdfSearchWorkload::average(const Task<Nothing, std::vector<MaterialEvaluation>>& task) const {
  const auto& materials = task.input;
  if (materials.size() != evaluated_materials()) throw RunError("the BRDF averages lack material evaluations");
  const auto names = model_names();
  std::vector<AverageRow> rows;
  const std::size_t training = settings_.evaluation.training.size();
  for (const bool testing : {false, true}) {
    const std::size_t begin = testing ? training : 0, end = testing ? materials.size() : training;
    if (begin == end) continue;
    for (std::size_t k = 0; k < names.size(); ++k) {
      std::vector<double> metric, l2, ssim;
      for (std::size_t m = begin; m < end; ++m) {
        metric.push_back(materials[m].models[k].metric_error);
        l2.push_back(materials[m].models[k].image_l2);
        ssim.push_back(materials[m].models[k].one_minus_ssim);
      }
      AverageRow row{testing ? "testing" : "training", names[k], mean(metric), mean(l2), mean(ssim)};
      if (!rows.empty() && k > 0) {
        const AverageRow& seed = rows[rows.size() - k];
        row.l2_reduction = reduction(row.image_l2, seed.image_l2);
        row.ssim_reduction = reduction(row.one_minus_ssim, seed.one_minus_ssim);
      }
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace pbrfit::jobs::brdf
