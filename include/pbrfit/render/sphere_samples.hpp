#pragma once
// The light samples of a sphere render (sphere_view.hpp) lit by an environment map, without occlusion:
// for every pixel on the sphere, `samples_per_pixel` directions drawn from the map's importance sampling
// at the points of the 2-D Halton sequence (integrate/halton.hpp), Cranley-Patterson rotated by an
// offset hashed from the pixel index. A sample's weight is what it adds to its pixel per unit BRDF:
//   weight = L(wi) cos(theta_i) / (pdf(wi) samples_per_pixel)   per channel,
// so a pixel's value is the sum over its samples of f(wi, wo) x weight. Directions are given in the
// pixel's local frame (SphereView::local_frame: normal +z); wo is the direction to the camera.
// Samples below the local horizon (cos theta_i <= 0) add nothing and are not visited or stored.
//
// visit_light_samples is the one sampling loop; SphereSamples stores what it visits once per
// (environment, view, sample count), so that many BRDFs are rendered or tabulated without re-sampling:
// per stored sample wi (single precision), the weight (single precision) and the MERL cell of (wi, wo)
// (computed in double precision before storing). Everything is deterministic: a pure function of the
// map, the view, the sample count and the pixel.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "pbrfit/geometry/vector.hpp"
#include "pbrfit/render/environment_map.hpp"
#include "pbrfit/render/rgb.hpp"
#include "pbrfit/render/sphere_view.hpp"

namespace pbrfit::render {

using SampleVisitor =
    std::function<void(std::size_t pixel, const Vector3& wi, const Vector3& wo, const Rgb& weight)>;

// The flat MERL cell (brdf/merl_grid.hpp) of a pair of local directions.
std::uint32_t merl_cell_of_pair(const Vector3& wi, const Vector3& wo);

// Visits the samples of the pixels of `range` in pixel order, then sample order; off-sphere pixels have none.
void visit_light_samples(const EnvironmentMap& environment, const SphereView& view, std::size_t samples_per_pixel,
                         PixelRange range, const SampleVisitor& visit);

class SphereSamples {
 public:
  // samples_per_pixel >= 1 (std::invalid_argument otherwise).
  SphereSamples(const EnvironmentMap& environment, const SphereView& view, std::size_t samples_per_pixel);

  const SphereView& view() const { return view_; }
  std::size_t samples_per_pixel() const { return samples_per_pixel_; }
  std::size_t size() const { return cell_.size(); }
  // The stored samples of `pixel` are first(pixel) .. first(pixel + 1) - 1.
  std::size_t first(std::size_t pixel) const { return first_[pixel]; }
  Vector3 wo(std::size_t pixel) const { return wo_[pixel]; }
  Vector3 wi(std::size_t sample) const {
    return {double(wi_[3 * sample]), double(wi_[3 * sample + 1]), double(wi_[3 * sample + 2])};
  }
  Rgb weight(std::size_t sample) const {
    return {double(weight_[3 * sample]), double(weight_[3 * sample + 1]), double(weight_[3 * sample + 2])};
  }
  std::uint32_t cell(std::size_t sample) const { return cell_[sample]; }
  // The stored samples of `range`, as visit_light_samples visits them (up to single-precision rounding).
  void visit(PixelRange range, const SampleVisitor& visit) const;

 private:
  SphereView view_;
  std::size_t samples_per_pixel_;
  std::vector<std::size_t> first_;  // pixels + 1 offsets
  std::vector<Vector3> wo_;    // per pixel, local (zero off the sphere)
  std::vector<float> wi_, weight_;  // 3 per sample
  std::vector<std::uint32_t> cell_;
};

}  // namespace pbrfit::render
