// The result layout and blocks of a genBRDF search's evaluation (brdf_search_workload.hpp): group
// `brdf/evaluation` (docs/results-brdf_search.md).
#include <cmath>

#include "pbrfit/jobs/brdf/brdf_inputs.hpp"
#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "result_tables.hpp"
#include "search_records.hpp"

namespace pbrfit::jobs::brdf {
namespace {

using store::ValueType;

constexpr const char* evaluation = "brdf/evaluation";

std::vector<double> indices(std::size_t n) {
  std::vector<double> out(n);
  for (std::size_t k = 0; k < n; ++k) out[k] = double(k);
  return out;
}

}  // namespace

store::Group BrdfSearchWorkload::evaluation_group() const {
  const auto& e = settings_.evaluation;
  const auto names = model_names();
  const std::size_t resolution = settings_.evaluation.scene->samples.view().resolution(), models = names.size();
  std::vector<std::string> materials = e.training, images = {"measured"};
  materials.insert(materials.end(), e.testing.begin(), e.testing.end());
  images.insert(images.end(), names.begin(), names.end());
  store::Group g;
  g.name = evaluation;
  g.description = "the seed, the references and chosen front members fitted to the training and testing materials, "
                  "rendered on the sphere under the scene's light and compared with the measured renders (Brady et al., "
                  "section 4)";
  g.attributes = {{"materials", joined(materials)},
                  {"training_materials", joined(e.training)},
                  {"testing_materials", joined(e.testing)},
                  {"models", joined(names)},
                  {"images", joined(images)},
                  {"display", "sRGB of the linear render x " + std::to_string(e.exposure) + ", clamped to [0, 1]"}};
  for (const auto& [key, value] : e.scene->attributes) g.attributes.emplace(key, value);
  g.axes = {{"material", indices(materials.size()), "index into the `materials` attribute (training, then testing)"},
            {"model", indices(models), "index into the `models` attribute"},
            {"image", indices(models + 1), "index into the `images` attribute: the measured render, then each model"},
            {"row", indices(resolution), "pixel row from the top"},
            {"column", indices(resolution), "pixel column from the left"},
            {"channel", indices(3), "red, green, blue"},
            {"parameter", indices(brdf_parameter_count), "p0..p3"}};
  store::Table renders{"renders", {"material", "image", "row", "column", "channel"},
                       "8-bit sRGB renders of the sphere (display samples, as in a PNG)", ValueType::u8};
  renders.chunk = {1, 1, resolution, resolution, 3};
  store::Table parameters{"parameters", {"material", "model", "channel", "parameter"},
                          "each model's parameters fitted to each material and channel", ValueType::f64};
  g.tables = {
      records("models", "model", "what was evaluated: the seed, the references, then the chosen members of the front",
              {{"model", ValueType::text, "its name in `models`"}, {"expression", ValueType::text, "the BRDF"},
               {"cost", ValueType::f64, "syntax tree size (nodes)"},
               {"training_error", ValueType::f64, "the search's error (NaN for the seed and the references)"}}),
      records("materials", "row", "a row per material and model, in the order of `materials`",
              {{"material", ValueType::text, "MERL name"}, {"set", ValueType::text, "training or testing"},
               {"model", ValueType::text, "model"}, {"metric_error", ValueType::f64, "sqrt(S') over the channels"},
               {"image_l2", ValueType::f64, "RGB RMS error of the display image against the measured render"},
               {"one_minus_ssim", ValueType::f64, "1 - SSIM of the display luminance"}}),
      records("averages", "row", "the mean errors per material set and model, and the reductions relative to the "
                                 "seed's mean (per cent; positive: better than the seed)",
              {{"set", ValueType::text, "training or testing"}, {"model", ValueType::text, "model"},
               {"metric_error", ValueType::f64, "mean metric error"}, {"image_l2", ValueType::f64, "mean image L2"},
               {"one_minus_ssim", ValueType::f64, "mean 1 - SSIM"},
               {"l2_reduction", ValueType::f64, "100 (1 - image_l2 / the seed's)"},
               {"ssim_reduction", ValueType::f64, "100 (1 - one_minus_ssim / the seed's)"}}),
      std::move(renders), std::move(parameters)};
  return g;
}

store::Block BrdfSearchWorkload::models_block(const FrontRecord& record) const {
  const auto models = evaluated_models(record);
  const auto names = model_names();
  store::Block block{evaluation, "models", {0}, {models.size()}};
  const std::size_t unsearched = 1 + settings_.evaluation.references.size();
  for (std::size_t k = 0; k < models.size(); ++k) {
    block.values.insert(block.values.end(), {models[k].size(), k < unsearched ? std::nan("") : models[k].error});
    block.texts.insert(block.texts.end(), {names[k], expression(models[k].tree)});
  }
  return block;
}

std::vector<store::Block> BrdfSearchWorkload::averages_blocks(const StageItem&, const std::vector<AverageRow>& rows) const {
  store::Block block{evaluation, "averages", {0}, {rows.size()}};
  for (const auto& r : rows) {
    block.values.insert(block.values.end(), {r.metric_error, r.image_l2, r.one_minus_ssim, r.l2_reduction, r.ssim_reduction});
    block.texts.insert(block.texts.end(), {r.set, r.model});
  }
  return {block};
}

void BrdfSearchWorkload::check_material(const StageItem&, const MaterialEvaluation& record) const {
  const std::size_t models = model_names().size(), resolution = settings_.evaluation.scene->samples.view().resolution();
  if (record.models.size() != models || record.renders.size() != (models + 1) * resolution * resolution * 3)
    throw RunError("a BRDF evaluation record does not match the job's models and resolution");
  std::size_t parameters = 0;
  for (const auto& model : record.models) parameters += model.parameters.size();
  if (parameters != models * 3 * brdf_parameter_count) throw RunError("a BRDF evaluation record has parameters missing");
}

std::vector<store::Block> BrdfSearchWorkload::material_blocks(const StageItem& at, const MaterialEvaluation& record) const {
  const auto names = model_names();
  const std::size_t m = at.item(), resolution = settings_.evaluation.scene->samples.view().resolution();
  store::Block rows{evaluation, "materials", {0}, {names.size()}};
  store::Block parameters{evaluation, "parameters", {m, 0, 0, 0}, {1, names.size(), 3, brdf_parameter_count}};
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto& model = record.models[k];
    rows.values.insert(rows.values.end(), {model.metric_error, model.image_l2, model.one_minus_ssim});
    rows.texts.insert(rows.texts.end(),
                      {evaluated_material(m), m < settings_.evaluation.training.size() ? "training" : "testing", names[k]});
    parameters.values.insert(parameters.values.end(), model.parameters.begin(), model.parameters.end());
  }
  store::Block renders{evaluation, "renders", {m, 0, 0, 0, 0}, {1, names.size() + 1, resolution, resolution, 3}};
  renders.values.assign(record.renders.begin(), record.renders.end());
  return {rows, parameters, renders};
}

}  // namespace pbrfit::jobs::brdf
