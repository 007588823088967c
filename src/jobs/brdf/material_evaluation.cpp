#include "pbrfit/jobs/brdf/material_evaluation.hpp"

#include <limits>

#include "pbrfit/jobs/brdf/analytic_brdf.hpp"
#include "pbrfit/jobs/brdf/brdf_inputs.hpp"
#include "pbrfit/jobs/brdf/candidate_score.hpp"
#include "pbrfit/render/display_transform.hpp"
#include "pbrfit/render/image_metrics.hpp"
#include "pbrfit/render/sphere_renderer.hpp"
#include "pbrfit/store/png_file.hpp"

namespace pbrfit::jobs::brdf {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

void append_render(MaterialEvaluation& out, const RgbImage& linear, double exposure) {
  const auto samples = store::png_samples(render::display(linear, exposure));
  out.renders.insert(out.renders.end(), samples.begin(), samples.end());
}

}  // namespace

MaterialEvaluation evaluate_on_material(const BrdfScene& metric, const BrdfScene& scene,
                                        const pbrfit::brdf::MerlTable& material, const std::string& name,
                                        std::span<const gp::SyntaxTree> models, const gp::ParameterFitOptions& fit,
                                        double exposure, const RandomStream& random) {
  const MetricData data(metric.table, {material}, {name});
  const auto mask = scene.samples.view().mask();
  const RgbImage measured = render::render_sphere(scene.samples, material);
  MaterialEvaluation out;
  append_render(out, measured, exposure);
  for (std::size_t k = 0; k < models.size(); ++k) {
    const auto compiled = gp::compile(models[k], brdf_parameter_count);
    ModelEvaluation model{nan, nan, nan, std::vector<double>(3 * brdf_parameter_count, nan)};
    RgbImage image = render::blank_render(scene.samples);
    if (compiled) {
      const auto score = score_candidate(*compiled, data, fit, random.derive(k));
      if (std::isfinite(score.error)) {
        image = render::render_sphere(scene.samples, analytic_brdf(*compiled, score.parameters));
        const auto images = render::compare_renders(measured, image, mask, exposure);
        model = {score.error, images.rgb_l2, images.one_minus_ssim, {}};
        for (const auto& channel : score.parameters) model.parameters.insert(model.parameters.end(), channel.begin(), channel.end());
      }
    }
    out.models.push_back(std::move(model));
    append_render(out, image, exposure);
  }
  return out;
}

}  // namespace pbrfit::jobs::brdf
