#pragma once
// How well a candidate BRDF fits a search's materials (Brady et al., section 3.6): its parameters fitted by
// Nelder-Mead from random starts to every material and colour channel separately (gp/parameter_fit.hpp), on
// the metric's datasets (metric_data.hpp), with the parts of the candidate no parameter touches computed
// once per fit (gp/fixed_part.hpp); the per-fit error sqrt(S') combined by the L2 norm over channels and
// materials.
//
// Fits run in the order material by material, channel by channel; with warm_start each one's first search
// begins at the parameters of the fit before it.
//
// Contract: deterministic for the same stream key (fit m, c draws from random.derive(3 m + c)); a candidate
// with a non-finite error on any fit scores worst_error (the remaining fits are skipped). When the error of
// the materials fitted so far exceeds abandon_above, the rest are skipped too: the score is then
// `abandoned` and its error a lower bound of the full one. Safe to call from many threads at once.
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/parameter_fit.hpp"
#include "pbrfit/gp/syntax_tree.hpp"
#include "pbrfit/jobs/brdf/metric_data.hpp"

namespace pbrfit::jobs::brdf {

struct CandidateScore {
  double error = gp::worst_error;
  std::vector<double> material_errors;          // sqrt of each material's S' summed over channels
  std::vector<std::vector<double>> parameters;  // [3 material + channel][parameter]
  std::size_t evaluations = 0;
  bool abandoned = false;
};

CandidateScore score_candidate(const gp::CompiledTree& candidate, const MetricData& data,
                               const gp::ParameterFitOptions& options, const RandomStream& random,
                               double abandon_above = gp::worst_error);

}  // namespace pbrfit::jobs::brdf
