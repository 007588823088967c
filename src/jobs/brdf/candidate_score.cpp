#include "pbrfit/jobs/brdf/candidate_score.hpp"

#include <cmath>

#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/fixed_part.hpp"

namespace pbrfit::jobs::brdf {
namespace {

// Where the next fit's first search may start (ParameterFitOptions::warm_start): the last fit's
// parameters. Once a fit has no finite error the score is worst_error whatever follows.
std::span<const double> previous_point(const CandidateScore& score) {
  if (score.parameters.empty()) return {};
  return score.parameters.back();
}

}  // namespace

CandidateScore score_candidate(const gp::CompiledTree& candidate, const MetricData& data,
                               const gp::ParameterFitOptions& options, const RandomStream& random,
                               double abandon_above) {
  CandidateScore score;
  double total = 0.0;
  for (std::size_t m = 0; m < data.materials(); ++m) {
    double material = 0.0;
    for (std::size_t c = 0; c < 3; ++c) {
      const auto folded = gp::fold_fixed_part(candidate.program, candidate.parameter_slots, data.channel(m, c).data);
      gp::BatchInterpreter<float> interpreter(folded.dataset);
      const auto fit = gp::fit_parameters(folded.program, folded.parameter_slots, interpreter, options,
                                          random.derive(3 * m + c), previous_point(score));
      score.evaluations += fit.evaluations;
      score.parameters.push_back(fit.parameters);
      material += fit.error * fit.error * data.channel(m, c).weight_sum;  // S' of this fit
    }
    score.material_errors.push_back(std::sqrt(material));
    total += material;
    if (!std::isfinite(total)) break;
    if (std::sqrt(total) > abandon_above && m + 1 < data.materials()) {
      score.abandoned = true;
      break;
    }
  }
  score.error = std::isfinite(total) ? std::sqrt(total) : gp::worst_error;
  return score;
}

}  // namespace pbrfit::jobs::brdf
