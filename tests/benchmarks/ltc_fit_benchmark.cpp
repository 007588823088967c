// Fits the 64 x 64 GGX LTC table on one thread in the paper's marching order (smooth end first, each cell
// warm-started from its predecessor) and compares every cell with the published table of Heitz et al. 2016
// (data/reference/ltc_ggx_heitz2016_64.csv): both fits are judged by the same estimators on a lattice finer
// than the objective's, with the same amplitude (our albedo), so only the matrices differ.
//   bench_ltc_fit [objective_points] [max_evaluations] [judge_points]
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "../unit/engines/ltc_reference_table.hpp"
#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/fit_error.hpp"
#include "pbrfit/ltc/ggx_table.hpp"
#include "pbrfit/ltc/isotropic_fit.hpp"
#include "pbrfit/ltc/shader_form.hpp"

using namespace pbrfit::ltc;

namespace {

struct CellComparison {
  TableCell cell;
  FitError ours;
  FitError theirs;
  double our_norm = 0.0;
  double their_norm = 0.0;
};

struct TableFit {
  std::vector<CellFit> fits;  // by flat index
  double seconds = 0.0;      // wall clock
  double cpu_seconds = 0.0;  // this process's CPU time (the machine may be shared)
  std::size_t evaluations = 0;
};

TableFit fit_table(const GgxTableLayout& layout, const CellFitOptions& options) {
  TableFit table;
  table.fits.resize(static_cast<std::size_t>(layout.size * layout.size));
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  for (const MarchingStep& step : marching_order(layout)) {
    const IsotropicParameters warm =
        step.predecessor ? table.fits[layout.flat_index(*step.predecessor)].parameters : IsotropicParameters{};
    CellFit& fit = table.fits[layout.flat_index(step.cell)];
    fit = fit_isotropic_cell(std::make_shared<pbrfit::brdf::GgxLobe>(layout.alpha(step.cell), layout.cos_theta_view(step.cell)), warm, options);
    table.evaluations += fit.evaluations;
  }
  table.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  table.cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return table;
}

std::vector<CellComparison> judge(const GgxTableLayout& layout, const TableFit& table,
                                  const std::vector<pbrfit::test::PublishedLtcCell>& published, std::size_t points) {
  std::vector<CellComparison> comparisons;
  for (const auto& reference : published) {
    const TableCell cell{reference.roughness_index, reference.view_index};
    const CellFit& fit = table.fits[layout.flat_index(cell)];
    const auto target = std::make_shared<pbrfit::brdf::GgxLobe>(layout.alpha(cell), layout.cos_theta_view(cell));
    const FitErrorEstimator estimator(target, points);
    const double amplitude = fit.moments.albedo;
    CellComparison c{cell, estimator.errors(LtcDistribution(fit.matrix, amplitude)),
                     estimator.errors(LtcDistribution(matrix_from_shader_form(reference.ltc1), amplitude)), amplitude,
                     reference.norm};
    comparisons.push_back(c);
  }
  return comparisons;
}

double fraction(const std::vector<CellComparison>& comparisons, double slack, bool cubed) {
  std::size_t count = 0;
  for (const auto& c : comparisons) {
    const double ours = cubed ? c.ours.cubed : c.ours.l2;
    const double theirs = cubed ? c.theirs.cubed : c.theirs.l2;
    if (ours <= theirs * (1.0 + slack)) ++count;
  }
  return static_cast<double>(count) / static_cast<double>(comparisons.size());
}

void print_worst(std::vector<CellComparison> comparisons, bool cubed) {
  const auto ratio = [cubed](const CellComparison& c) {
    return cubed ? c.ours.cubed / c.theirs.cubed : c.ours.l2 / c.theirs.l2;
  };
  std::sort(comparisons.begin(), comparisons.end(),
            [&](const CellComparison& a, const CellComparison& b) { return ratio(a) > ratio(b); });
  std::printf("worst cells by %s ratio (ours / theirs):\n", cubed ? "cubed-error" : "L2");
  std::printf("| a | t | ours | theirs | ratio |\n|---|---|---|---|---|\n");
  for (std::size_t i = 0; i < 8 && i < comparisons.size(); ++i) {
    const auto& c = comparisons[i];
    std::printf("| %d | %d | %.4g | %.4g | %.4f |\n", c.cell.roughness_index, c.cell.view_index,
                cubed ? c.ours.cubed : c.ours.l2, cubed ? c.theirs.cubed : c.theirs.l2, ratio(c));
  }
}

}  // namespace

int main(int argc, char** argv) {
  CellFitOptions options;
  options.metric_points = 0;  // judged below, outside the timed fit
  if (argc > 1) options.objective_points = static_cast<std::size_t>(std::atoi(argv[1]));
  if (argc > 2) options.max_evaluations = static_cast<std::size_t>(std::atoi(argv[2]));
  const std::size_t judge_points = argc > 3 ? static_cast<std::size_t>(std::atoi(argv[3])) : 4096;
  const GgxTableLayout layout;
  const auto published = pbrfit::test::read_published_ltc_table(PBRFIT_SOURCE_DIR
                                                                "/data/reference/ltc_ggx_heitz2016_64.csv");

  const TableFit table = fit_table(layout, options);
  const auto comparisons = judge(layout, table, published, judge_points);
  const double cells = static_cast<double>(comparisons.size());
  std::printf("objective points %zu, max evaluations %zu, judge points %zu\n", options.objective_points,
              options.max_evaluations, judge_points);
  std::printf("fit time %.3f s wall, %.3f s CPU (%.3f ms CPU per cell), evaluations %zu (%.1f per cell)\n",
              table.seconds, table.cpu_seconds, 1e3 * table.cpu_seconds / cells, table.evaluations,
              static_cast<double>(table.evaluations) / cells);
  std::printf("cells with our cubed error <= theirs: %.2f %% (within 1 %%: %.2f %%)\n",
              100.0 * fraction(comparisons, 0.0, true), 100.0 * fraction(comparisons, 0.01, true));
  std::printf("cells with our L2 error <= theirs:    %.2f %% (within 1 %%: %.2f %%)\n",
              100.0 * fraction(comparisons, 0.0, false), 100.0 * fraction(comparisons, 0.01, false));
  double worst_norm = 0.0;
  for (const auto& c : comparisons) worst_norm = std::max(worst_norm, std::abs(c.our_norm - c.their_norm));
  std::printf("largest |our norm - published norm|: %.4g\n", worst_norm);
  print_worst(comparisons, true);
  print_worst(comparisons, false);
  return 0;
}
