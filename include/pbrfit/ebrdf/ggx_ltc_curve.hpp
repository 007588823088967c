#pragma once
// The LTC of the base GGX lobe (one roughness) as a function of the view elevation: what MIP-0 shading
// uses (Heitz et al. 2016) in the ground truth, the naive mip-mapped render and below two texels per pixel.
// Fitted once by ltc/isotropic_fit at `points` views with sqrt(1 - cos theta) uniform in [0, 1) (the
// published table's view axis), marching from the normal view towards grazing, each fit warm-starting the
// next; looked up by linear interpolation of M and of the amplitude (the lobe's albedo).
//
// Invariants: M maps cosine directions to the lobe in the frame where the view is (sin theta, 0, cos theta);
// lookups clamp cos theta to [0.01, 1]; deterministic.
#include <cstddef>
#include <vector>

#include "pbrfit/ebrdf/mip_tables.hpp"

namespace pbrfit::ebrdf {

class GgxLtcCurve {
 public:
  GgxLtcCurve(double alpha, std::size_t points = 32);
  LtcLookup at(double cos_theta) const;

 private:
  std::vector<LtcLookup> fits_;
};

}  // namespace pbrfit::ebrdf
