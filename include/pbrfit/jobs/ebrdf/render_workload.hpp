#pragma once
// Job kind `ebrdf_render` as a workload: the comparison of Nahmias 2022, chapter 4, for a finished `ebrdf`
// result. One item per (scene, distance): the plane rendered by the ground truth, the naive mip-mapped
// normals and the prefiltered LTCs (ebrdf/plane_renderer.hpp), stored as sRGB display images, with each
// method's MSE and SSIM against the ground truth over the pixels that see the plane (display values in
// [0, 1]), each method's energy (mean linear radiance over those pixels, and over the highlight: the pixels
// where the ground truth has at least a quarter of its brightest pixel's radiance) and the texels per pixel
// at the image centre. The layout is docs/results-ebrdf_render.md.
#include <memory>
#include <string>
#include <vector>

#include "pbrfit/ebrdf/ggx_ltc_curve.hpp"
#include "pbrfit/ebrdf/plane_renderer.hpp"
#include "pbrfit/jobs/ebrdf/prefiltered_tables.hpp"
#include "pbrfit/runtime/staged_workload.hpp"

namespace pbrfit::jobs::ebrdf {

struct RenderSettings {
  std::string tables_path;
  std::shared_ptr<const PrefilteredTables> tables;
  std::vector<pbrfit::ebrdf::SceneView> scenes;
  std::vector<double> distances;
  std::size_t resolution = 128;
  pbrfit::ebrdf::Shading shading;
  double exposure = 1.0;
};

struct RenderSummary {
  std::uint64_t images = 0, ours_better = 0, compared = 0;  // compared: images with >= 2 texels per pixel
  std::uint64_t energy_held = 0;  // images where ours is within 5 % of the ground truth's energy
};

class RenderWorkload final : public runtime::StagedWorkload<RenderSummary> {
 public:
  explicit RenderWorkload(RenderSettings settings);

  store::ResultLayout layout() const override;

 private:
  struct Rendered {
    std::vector<std::uint8_t> display;  // [method][row][column][3]
    double naive_mse = 0.0, ours_mse = 0.0, texels_per_pixel = 0.0;
    double naive_ssim = 0.0, ours_ssim = 0.0;
    std::vector<double> energy, highlight_energy;  // [method]: mean linear radiance
    template <class Archive>
    void serialize(Archive& archive) {
      archive(display, naive_mse, ours_mse, texels_per_pixel, naive_ssim, ours_ssim, energy, highlight_energy);
    }
  };

  std::uint64_t view_count(std::uint32_t) const { return settings_.scenes.size() * settings_.distances.size(); }
  Rendered render(const runtime::StageTask<Nothing, Nothing>& task) const;
  void check_render(const runtime::StageItem& at, const Rendered& rendered) const;
  std::vector<store::Block> render_blocks(const runtime::StageItem& at, const Rendered& rendered) const;
  void fold_render(Summary& summary, const runtime::StageItem& at, const Rendered& rendered) const;
  std::string headline_of(const Summary& summary) const override;

  RenderSettings settings_;
  pbrfit::ebrdf::GgxLtcCurve base_ltc_;
};

}  // namespace pbrfit::jobs::ebrdf
