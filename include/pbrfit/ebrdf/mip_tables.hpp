#pragma once
// A prefiltered LTC mip hierarchy of one component, as the renderer reads it (the tables of
// docs/results-ebrdf.md): level l = 1 .. levels() holds, per mip texel and tabulated view, the 9 entries of M
// and the amplitude. lookup() interpolates the way a shader would: bilinearly between the 4 nearest mip
// texels (the map tiles, so coordinates wrap), bilinearly between the 4 nearest views (theta clamped to the
// table, phi wrapping), and linearly between the two mip levels around a fractional level.
//
// Invariants: every level has views.count() entries per texel and side = map side >> level; a level
// clamps to [1, levels()]; deterministic.
#include <cstddef>
#include <vector>

#include "pbrfit/ebrdf/view_grid.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ebrdf {

struct LtcLevel {
  std::size_t side = 1;
  std::vector<float> matrices;    // [v][u][view][9]
  std::vector<float> amplitudes;  // [v][u][view]
};

struct LtcLookup {
  Matrix3 matrix = Matrix3::Identity();
  double amplitude = 0.0;
};

// One mip texel's lobe (interpolated between views) and its weight in a lookup.
struct WeightedLtc {
  double weight = 0.0;
  LtcLookup lobe;
};

// The direction a component's lobe follows as the view turns.
enum class LobeAxis { normal, mirror };

class LtcMipTables {
 public:
  // levels[0] is mip level 1. Throws std::invalid_argument when sizes do not match.
  LtcMipTables(ViewGrid views, std::vector<LtcLevel> levels, LobeAxis axis = LobeAxis::normal);

  std::size_t levels() const { return levels_.size(); }
  const ViewGrid& views() const { return views_; }
  LobeAxis lobe_axis() const { return axis_; }
  // (u, v) in texture space (any real: the map tiles), theta and phi of the view in the geometric frame.
  LtcLookup lookup(double level, double u, double v, double theta, double phi) const;
  // The up to 8 mip texels a lookup blends (4 per level, 2 levels), each interpolated between views,
  // with their weights (summing to 1): for blending what each lobe shades rather than the matrices.
  // lookup() is their weighted sum.
  std::vector<WeightedLtc> texel_lobes(double level, double u, double v, double theta, double phi) const;

 private:
  void accumulate_views(const LtcLevel& table, std::size_t texel, double theta, double phi, double weight,
                        LtcLookup& sum) const;

  ViewGrid views_;
  std::vector<LtcLevel> levels_;
  LobeAxis axis_;
};

}  // namespace pbrfit::ebrdf
