#pragma once
// The evaluation of genBRDF's section 4 for one material: each model (a BRDF expression with parameters
// p0..p3) fitted to the material by the metric of `metric` (candidate_score.hpp, per channel; the search's
// scene, so a fit here is the search's fit done more thoroughly), the sphere of `scene` rendered
// with the measured data and with every fit under its light (render/sphere_renderer.hpp), and each
// fit's render compared with the measured one: RGB L2 and 1 - SSIM of the display images at `exposure`
// (render/image_metrics.hpp).
//
// Invariants: deterministic for the same stream (model k fits from random.derive(k)); renders holds
// 1 + models images (the measured first), each resolution x resolution x 3 display samples (8 bits,
// rows from the top); a model that does not compile or fit gets NaN errors and a black render.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pbrfit/brdf/merl_table.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/parameter_fit.hpp"
#include "pbrfit/gp/syntax_tree.hpp"
#include "pbrfit/jobs/brdf/brdf_scene.hpp"

namespace pbrfit::jobs::brdf {

struct ModelEvaluation {
  double metric_error = 0.0;     // sqrt(S') summed over channels
  double image_l2 = 0.0;
  double one_minus_ssim = 0.0;
  std::vector<double> parameters;  // 3 channels x 4 parameters
  template <class Archive>
  void serialize(Archive& archive) {
    archive(metric_error, image_l2, one_minus_ssim, parameters);
  }
};

struct MaterialEvaluation {
  std::vector<ModelEvaluation> models;
  std::vector<std::uint8_t> renders;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(models, renders);
  }
};

MaterialEvaluation evaluate_on_material(const BrdfScene& metric, const BrdfScene& scene,
                                        const pbrfit::brdf::MerlTable& material, const std::string& name,
                                        std::span<const gp::SyntaxTree> models, const gp::ParameterFitOptions& fit,
                                        double exposure, const RandomStream& random);

}  // namespace pbrfit::jobs::brdf
