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

#include "pbrfit/ebrdf/base_lobe.hpp"
#include "pbrfit/jobs/ebrdf/ebrdf_items.hpp"
#include "pbrfit/jobs/ebrdf/ebrdf_settings.hpp"
#include "pbrfit/runtime/staged_workload.hpp"

namespace pbrfit::jobs::ebrdf {

inline constexpr std::size_t values_per_fit = 11;  // 9 matrix entries, amplitude, error

std::string level_group(const ComponentSettings& component, std::size_t level);

struct EbrdfSummary {
  std::uint64_t fits = 0;
  std::uint64_t error_sum_micro = 0;  // sum of round(1e6 error): an integer, exact in any order
  double max_error = 0.0;
};

class EbrdfWorkload final : public runtime::StagedWorkload<EbrdfSummary> {
 public:
  explicit EbrdfWorkload(EbrdfSettings settings);

  store::ResultLayout layout() const override;
  std::string work_unit() const override { return "fits"; }

 private:
  // A tile's fits, [texel y][texel x][view][values_per_fit] with the tile's texels row-major; empty for item 0.
  using TileFits = std::vector<float>;
  using Task = runtime::StageTask<Nothing, Nothing>;

  std::uint64_t item_total(std::uint32_t) const { return items_.count(); }
  TileFits compute_item(const Task& task) const;
  void check_item(const runtime::StageItem& at, const TileFits& fits) const;
  std::vector<store::Block> item_blocks(const runtime::StageItem& at, const TileFits& fits) const;
  void fold_item(Summary& summary, const runtime::StageItem& at, const TileFits& fits) const;
  std::string headline_of(const Summary& summary) const override;
  double work_done_in(const Summary& summary) const override { return double(summary.fits); }

  TileFits fit_tile(const TileItem& tile, const Task& task) const;
  std::size_t fits_in(const TileItem& tile) const;

  EbrdfSettings settings_;
  TileItems items_;
  std::vector<pbrfit::ebrdf::BaseLobeLtc> base_lobes_;  // per component
};

}  // namespace pbrfit::jobs::ebrdf
