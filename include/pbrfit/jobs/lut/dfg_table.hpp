#pragma once
// The split-sum DFG table as a workload of one stage (runtime/staged_workload.hpp): an item per roughness row, each integrating every
// n.v entry of the row (and, with multiple scattering, the row's Kulla-Conty average albedo; with cloth, the
// cloth channel of brdf/cloth_albedo.hpp at every entry).
#include <cstddef>
#include <vector>

#include "pbrfit/brdf/ggx.hpp"
#include "pbrfit/brdf/roughness.hpp"
#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/jobs/lut/table_axis.hpp"
#include "pbrfit/runtime/staged_workload.hpp"

namespace pbrfit::jobs::lut {

struct DfgSettings {
  brdf::SmithVisibility visibility = brdf::SmithVisibility::height_correlated;
  brdf::RoughnessParametrization roughness = brdf::RoughnessParametrization::perceptual;
  bool multiple_scattering = false;
  bool cloth = false;
  std::size_t n_dot_v_count = 128;
  std::size_t roughness_count = 128;
  Placement placement = Placement::centres;
  integrate::AdaptiveOptions integration;  // per entry
};

// What the headline reports, folded row by row.
struct DfgSummary {
  double worst_error = 0.0;
  double evaluations = 0.0;  // a sum of integers: exact in any order below 2^53
  std::uint64_t entries = 0, above_tolerance = 0;
};

class DfgTable final : public runtime::StagedWorkload<DfgSummary> {
 public:
  explicit DfgTable(const DfgSettings& settings);

  store::ResultLayout layout() const override;

 private:
  // A row's result, as computed and as stored in checkpoints; the cloth vectors are empty without cloth.
  struct Row {
    std::vector<double> scale, bias, error_estimate, evaluations;
    double average_energy = 0.0;
    double average_energy_error = 0.0;
    std::vector<double> cloth, cloth_error, cloth_evaluations;
    template <class Archive>
    void serialize(Archive& archive) {
      archive(scale, bias, error_estimate, evaluations, average_energy, average_energy_error, cloth, cloth_error,
              cloth_evaluations);
    }
  };
  using Task = runtime::StageTask<Nothing, Nothing>;

  std::uint64_t row_count(std::uint32_t) const { return roughness_.size(); }
  Row compute_row(const Task& task) const;
  void check_row(const runtime::StageItem& at, const Row& row) const;
  std::vector<store::Block> row_blocks(const runtime::StageItem& at, const Row& row) const;
  void fold_row(Summary& summary, const runtime::StageItem& at, const Row& row) const;
  std::string headline_of(const Summary& summary) const override;

  double alpha(std::uint64_t row) const;
  // Throws RunError (naming the entry and what to change) when an integral missed the tolerance.
  void require_converged(bool converged, double error, std::size_t evaluations, const std::string& what) const;

  DfgSettings settings_;
  std::vector<double> n_dot_v_;
  std::vector<double> roughness_;
};

}  // namespace pbrfit::jobs::lut
