#pragma once
// Job kind `ebrdf` as a workload: LTC mip hierarchies that prefilter a normal map (Nahmias 2022). One
// stage; item 0 stores the MIP-0 normals, every other item one tile of one mip level of one component
// (ebrdf_items.hpp): for each texel of the tile and each tabulated view, the footprint's eBRDF samples
// (ebrdf/footprint_samples.hpp) get one LTC (ebrdf/ebrdf_fit.hpp), views in order (theta-major), each
// warm-started from the previous view of the same texel.
//
// Results: per texel and view, the 9 matrix entries, the amplitude and the fit error, as float32 (what the
// tables hold). The layout is docs/results-ebrdf.md.
#include <cstdint>
#include <string>
#include <vector>

#include "pbrfit/ebrdf/albedo_curve.hpp"
#include "pbrfit/jobs/ebrdf/ebrdf_items.hpp"
#include "pbrfit/jobs/ebrdf/ebrdf_settings.hpp"
#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::jobs::ebrdf {

inline constexpr std::size_t values_per_fit = 11;  // 9 matrix entries, amplitude, error

std::string level_group(const ComponentSettings& component, std::size_t level);

class EbrdfWorkload final : public runtime::Workload {
 public:
  explicit EbrdfWorkload(EbrdfSettings settings);

  store::ResultLayout layout() const override;
  std::uint64_t item_count(std::uint32_t) const override { return items_.count(); }
  Bytes compute(const runtime::ItemTask& task) const override;
  std::vector<store::Block> blocks(WorkItemId id, const Bytes& result) const override;
  void fold_summary(Bytes& summary, WorkItemId id, const Bytes& result) const override;
  std::string headline(const Bytes& summary) const override;
  double work_done(const Bytes& summary) const override;
  std::string work_unit() const override { return "fits"; }

 private:
  struct Summary {
    std::uint64_t fits = 0;
    std::uint64_t error_sum_micro = 0;  // sum of round(1e6 error): an integer, exact in any order
    double max_error = 0.0;
  };
  // [texel y][texel x][view][values_per_fit], the tile's texels row-major.
  std::vector<float> fit_tile(const TileItem& tile, const runtime::ItemTask& task) const;
  std::vector<float> decode(WorkItemId id, const Bytes& result) const;
  std::size_t fits_in(const TileItem& tile) const;

  EbrdfSettings settings_;
  TileItems items_;
  std::vector<pbrfit::ebrdf::AlbedoCurve> albedo_;  // per component
};

}  // namespace pbrfit::jobs::ebrdf
