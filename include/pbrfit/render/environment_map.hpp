#pragma once
// Incident radiance from every direction, as an equirectangular RGB image (equirectangular.hpp: +y up,
// row r holds the polar angle from +y in [r, r+1) pi / H, column c the azimuth about +y from +z in
// [c, c+1) 2 pi / W), constant over each texel; and importance sampling of it.
//
// Sampling draws a texel with probability proportional to luminance x solid angle (a piecewise-constant
// marginal over rows, then a conditional over that row's columns), then a direction uniformly in the
// texel's solid angle. Its density per steradian is therefore luminance(texel) / P, where
// P = sum over texels of luminance x solid angle.
//
// Invariants: every radiance is finite and >= 0 and P > 0 (std::invalid_argument otherwise); pdf()
// integrates to 1 over the sphere and equals the density sample() draws from (the pdf it returns);
// texels of luminance 0 are never sampled (they are black in every channel, as radiance is >= 0).
#include <cstddef>
#include <vector>

#include "pbrfit/core/rgb_image.hpp"
#include "pbrfit/geometry/vector.hpp"
#include "pbrfit/render/equirectangular.hpp"
#include "pbrfit/render/piecewise_constant.hpp"
#include "pbrfit/render/rgb.hpp"

namespace pbrfit::render {

struct EnvironmentSample {
  Vector3 direction = Vector3::UnitY();  // unit, world frame
  Rgb radiance = {0.0, 0.0, 0.0};
  double pdf = 0.0;  // per steradian
};

class EnvironmentMap {
 public:
  explicit EnvironmentMap(RgbImage radiance);

  const RgbImage& image() const { return image_; }
  Rgb radiance(const Vector3& direction) const;
  double pdf(const Vector3& direction) const;
  // (u1, u2) in [0, 1)^2: u1 picks the row and the polar angle inside it, u2 the column and the azimuth.
  EnvironmentSample sample(double u1, double u2) const;
  // P: luminance integrated over the sphere.
  double luminous_power() const { return rows_.total_weight(); }

 private:
  Texel texel_at(const Vector3& direction) const;
  double texel_pdf(const Texel& texel) const;

  RgbImage image_;
  std::vector<PiecewiseConstant> columns_;  // per row, over its columns
  PiecewiseConstant rows_;                  // over rows, by each row's total weight
};

}  // namespace pbrfit::render
