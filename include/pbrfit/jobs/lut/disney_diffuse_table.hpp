#pragma once
// The Disney diffuse environment-lighting table (Pesce & Iwanicki 2015, section 6) as a workload: one work
// item per roughness row; for every n.v of the row, the cosine-weighted Disney diffuse BRDF projected onto
// SH by adaptive cubature, its optimal linear direction, the blend factor beta between n and v and the zonal
// coefficients ZH0..ZH2 about that direction (brdf/disney_diffuse_lobe.hpp), beside the course's closed-form
// fits at the same entry (brdf/disney_diffuse_course_fit.hpp) and their deviations from the integrals.
#include <cstddef>
#include <vector>

#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/jobs/lut/table_axis.hpp"
#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::jobs::lut {

struct DisneyDiffuseSettings {
  std::size_t n_dot_v_count = 32;
  std::size_t roughness_count = 32;
  Placement placement = Placement::centres;
  integrate::AdaptiveOptions integration;  // per entry
};

class DisneyDiffuseTable final : public runtime::Workload {
 public:
  explicit DisneyDiffuseTable(const DisneyDiffuseSettings& settings);

  store::ResultLayout layout() const override;
  std::uint64_t item_count(std::uint32_t) const override { return roughness_.size(); }
  Bytes compute(const runtime::ItemTask& task) const override;
  std::vector<store::Block> blocks(WorkItemId id, const Bytes& result) const override;
  void fold_summary(Bytes& summary, WorkItemId id, const Bytes& result) const override;
  std::string headline(const Bytes& summary) const override;

 private:
  // Per entry of a row: 9 SH coefficients, the direction (x, z), beta, ZH0..2, error estimate, evaluations.
  static constexpr std::size_t values_per_entry = 16;
  std::vector<double> decode(const Bytes& bytes) const;

  DisneyDiffuseSettings settings_;
  std::vector<double> n_dot_v_;
  std::vector<double> roughness_;
};

}  // namespace pbrfit::jobs::lut
