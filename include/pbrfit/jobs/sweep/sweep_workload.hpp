#pragma once
// A hierarchical parameter sweep as a runtime workload (sweep/sweep_schedule.hpp): a stage per level (or
// per marching step of a level), an item per cell. A cell's item input is the fits of the cells that
// warm-start it, taken from the kept results of earlier stages; a fit is kept until the last stage that
// reads it. Each cell fits every model of the job against the problem's target for that cell.
//
// Result layout: a group `<model>/level<l>` per model and level, over the level's axes, with one table
// per parameter (role parameter), `error` (role error), `evaluations` (count), `start` (which start won,
// start_code_labels) and `global_search` (whether DE ran), and the model's outputs; a vector output has an
// extra innermost axis `<output>_component`. The last level is the requested grid.
//
// Projections (Pesce & Iwanicki 2015, section 4.2.2: fitted parameters averaged over incidence): with
// `projections`, a last stage has one item per projected axis, whose input is every fit of the last level;
// it writes `<model>/level<L>_mean_over_<axis>` over the other axes, with each parameter's and the error's
// mean and standard deviation over the projected axis.
//
// Check render (problems with a RenderPlan, e.g. LTC tables): a last stage has one item per model, image and
// band of rows, whose input is the last level's fits of the cells the image reads; it writes `<model>/render` over
// (image axis, row, column) with a table per layer of the plan, and with curves `<model>/<curves group>` over
// (image axis, set, position) (docs/results-sweep.md).
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "pbrfit/jobs/sweep/cell_result.hpp"
#include "pbrfit/jobs/sweep/sweep_settings.hpp"
#include "pbrfit/runtime/staged_workload.hpp"

namespace pbrfit::jobs::sweep {

// The running summary (sweep_summary.cpp): cells done per level; per model the best and worst error, the
// errors' distribution (for the headline's percentiles), the evaluations and how often the global search ran.
struct SweepSummary {
  static constexpr std::size_t models = 8;
  static constexpr std::size_t levels = 32;
  // Finite errors counted by log10 in bins of 1/8 decade from 1e-40 to 1e+40; smaller errors (zero too)
  // count in the first bin, larger ones in the last.
  static constexpr int bins_per_decade = 8;
  static constexpr int lowest_decade = -40;
  static constexpr std::size_t error_bins = 80 * bins_per_decade;
  struct Model {
    double best = std::numeric_limits<double>::infinity();
    double worst = 0.0;
    std::uint64_t evaluations = 0;
    std::uint64_t global_runs = 0;
    std::uint64_t non_finite = 0;
    std::uint32_t error_counts[error_bins] = {};
  };
  std::uint64_t cells = 0;
  std::uint64_t level_cells[levels] = {};
  Model model[models] = {};
};

class SweepWorkload final : public runtime::StagedWorkload<SweepSummary> {
 public:
  explicit SweepWorkload(SweepSettings settings);

  store::ResultLayout layout() const override;

  const pbrfit::sweep::SweepSchedule& schedule() const { return schedule_; }

 private:
  // A cell's warm starts: the kept fits of the cells that start it, and whether each is a neighbour or a parent.
  struct WarmStarts {
    std::vector<StartCode> codes;
    std::vector<CellFits> fits;
    template <class Archive>
    void serialize(Archive& archive) {
      archive(codes, fits);
    }
  };
  // A projection's input: every fit of the last level, in flat cell order.
  using LastLevel = std::vector<CellFits>;
  // A projection's result: for each model, each projected cell (flat order), each parameter then the error:
  // mean and standard deviation.
  using Projection = std::vector<double>;
  using StageItem = runtime::StageItem;

  // Levels (sweep_workload.cpp): step s of "levels" is stage s of the schedule.
  std::uint64_t cell_count(std::uint32_t step) const { return schedule_.stages()[step].cells.size(); }
  WarmStarts warm_starts(std::uint32_t step, std::uint64_t item, const runtime::KeptResults& kept) const;
  CellFits fit(const runtime::StageTask<Nothing, WarmStarts>& task) const;
  void check_cell(const StageItem& at, const CellFits& fits) const;
  std::vector<store::Block> cell_blocks(const StageItem& at, const CellFits& fits) const;
  std::uint32_t cell_kept_through(const StageItem& at) const;
  void fold_cell(Summary& summary, const StageItem& at, const CellFits& fits) const;  // sweep_summary.cpp
  std::string headline_of(const Summary& summary) const override;

  std::string group_name(std::size_t model, std::uint32_t level) const;
  store::Group level_group(std::size_t model, std::uint32_t level) const;
  std::uint32_t final_level() const { return std::uint32_t(schedule_.levels().size() - 1); }

  // Projections (sweep_projection.cpp).
  std::uint64_t projection_count(std::uint32_t) const { return settings_.projections.size(); }
  LastLevel last_level(std::uint32_t step, std::uint64_t item, const runtime::KeptResults& kept) const;
  Projection project(const runtime::StageTask<Nothing, LastLevel>& task) const;
  void check_projection(const StageItem& at, const Projection& values) const;
  std::vector<store::Block> projection_blocks(const StageItem& at, const Projection& values) const;
  std::string projection_name(std::size_t model, std::size_t projection) const;
  pbrfit::sweep::LevelGrid projected_grid(std::size_t projection) const;
  store::Group projection_group(std::size_t model, std::size_t projection) const;

  // The check render (sweep_render.cpp): items run over bands, then images, then models.
  using RenderCells = std::vector<CellFits>;
  using RenderImage = std::vector<double>;
  std::uint64_t render_count(std::uint32_t) const;
  RenderCells render_cells(std::uint32_t step, std::uint64_t item, const runtime::KeptResults& kept) const;
  RenderImage render(const runtime::StageTask<Nothing, RenderCells>& task) const;
  void check_render(const StageItem& at, const RenderImage& image) const;
  std::vector<store::Block> render_blocks(const StageItem& at, const RenderImage& image) const;
  store::Group render_group(std::size_t model) const;
  store::Group curves_group(std::size_t model) const;

  SweepSettings settings_;
  std::vector<ModelInfo> models_;  // the job's models, in job order
  std::vector<FitShape> shapes_;
  pbrfit::sweep::SweepSchedule schedule_;
  std::optional<RenderPlan> render_plan_;
};

}  // namespace pbrfit::jobs::sweep
