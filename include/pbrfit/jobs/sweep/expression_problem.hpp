#pragma once
// Sweep problem `expression`: the user states the target and the model as expression texts
// (gp/expression_parser.hpp) over a domain, and the grid axes and the model's parameters in the job. Per
// cell, the error is the L^p distance between target and model over the domain,
//   ( integral over the domain of |target - model|^p )^(1/p),   or max |target - model| for p = inf,
// estimated by globally adaptive cubature at the tolerance the optimizer asks for (cooperative accuracy;
// boxes of up to 3 dimensions, the sphere and the hemisphere in (z, phi)) or by deterministic QMC
// (integrate/qmc_nodes.hpp: Halton points in boxes; uniform and cosine-weighted directions combined by MIS
// on the sphere and the hemisphere). Expressions read the domain's inputs (interval and box: the names the
// job gives; sphere and hemisphere: wx, wy, wz) and the cell's axis values by the axes' names; the model also
// reads its parameters. A non-finite value anywhere makes the error +inf (an infeasible point).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "pbrfit/gp/program.hpp"
#include "pbrfit/gp/program_builder.hpp"
#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/jobs/sweep/sweep_problem.hpp"

namespace pbrfit::jobs::sweep {

enum class ExpressionDomain { interval, box, sphere, hemisphere };

struct ExpressionProblemSettings {
  ExpressionDomain domain = ExpressionDomain::interval;
  std::vector<std::string> inputs;   // the domain's variables
  std::vector<double> lower, upper;  // interval and box
  std::vector<ProblemAxis> axes;
  std::string target_text, model_text;
  gp::Program target, model;
  std::vector<std::vector<gp::ConstantSlot>> parameter_slots;  // of the model, per parameter
  std::vector<optimize::Parameter> parameters;
  std::vector<double> start;  // default start, one per parameter
  double p = 2.0;             // 1, 2, 3 or +inf
  bool qmc = false;
  std::size_t samples = 4096;        // QMC points (per strategy on directions)
  integrate::AdaptiveOptions integration;  // abs_tolerance is the final tolerance
  double coarse_tolerance = 1e-3;
};

std::unique_ptr<SweepProblem> make_expression_problem(ExpressionProblemSettings settings);

}  // namespace pbrfit::jobs::sweep
