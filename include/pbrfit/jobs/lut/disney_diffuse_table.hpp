#pragma once
// The Disney diffuse environment-lighting table (Pesce & Iwanicki 2015, section 6) as a workload of one stage: an
// item per roughness row; for every n.v of the row, the cosine-weighted Disney diffuse BRDF projected onto
// SH by adaptive cubature, its optimal linear direction, the blend factor beta between n and v and the zonal
// coefficients ZH0..ZH2 about that direction (brdf/disney_diffuse_lobe.hpp), beside the course's closed-form
// fits at the same entry (brdf/disney_diffuse_course_fit.hpp) and their deviations from the integrals.
#include <cstddef>
#include <vector>

#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/jobs/lut/table_axis.hpp"
#include "pbrfit/runtime/staged_workload.hpp"

namespace pbrfit::jobs::lut {

struct DisneyDiffuseSettings {
  std::size_t n_dot_v_count = 32;
  std::size_t roughness_count = 32;
  Placement placement = Placement::centres;
  integrate::AdaptiveOptions integration;  // per entry
};

struct DisneyDiffuseSummary {
  double worst_estimate = 0.0;
  double worst_beta_deviation = 0.0;
  std::uint64_t entries = 0;
};

class DisneyDiffuseTable final : public runtime::StagedWorkload<DisneyDiffuseSummary> {
 public:
  explicit DisneyDiffuseTable(const DisneyDiffuseSettings& settings);

  store::ResultLayout layout() const override;

 private:
  // A row: per entry 9 SH coefficients, the direction (x, z), beta, ZH0..2 and the error estimate.
  using Row = std::vector<double>;
  static constexpr std::size_t values_per_entry = 16;

  std::uint64_t row_count(std::uint32_t) const { return roughness_.size(); }
  Row compute_row(const runtime::StageTask<Nothing, Nothing>& task) const;
  void check_row(const runtime::StageItem& at, const Row& row) const;
  std::vector<store::Block> row_blocks(const runtime::StageItem& at, const Row& row) const;
  void fold_row(Summary& summary, const runtime::StageItem& at, const Row& row) const;
  std::string headline_of(const Summary& summary) const override;

  DisneyDiffuseSettings settings_;
  std::vector<double> n_dot_v_;
  std::vector<double> roughness_;
};

}  // namespace pbrfit::jobs::lut
