#pragma once
// Fits the named parameters of a program (the constants in parameter_slots[k] all hold parameter k) to a
// dataset, as genBRDF fits each candidate BRDF to each material and colour channel (Brady et al., section
// 3.6): Nelder-Mead with restarts from `starts` random points, each parameter drawn uniformly in
// [start_lower, start_upper] and searched within [lower, upper]; the best point of all starts wins.
// Parameters no slot holds are left at 0 and not searched. With warm_start and a `previous` point (say the
// fit of a neighbouring colour channel), the first start begins there instead, clamped into the box; the
// other starts are drawn as before.
//
// Contract: deterministic for the same stream state (start s draws from random.derive(s)); at most
// starts x evaluations_per_start error evaluations; the reported error is the interpreter's error at the
// reported parameters (worst_error when no start gave a finite one).
#include <cstddef>
#include <span>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/program_builder.hpp"

namespace pbrfit::gp {

struct ParameterFitOptions {
  std::size_t starts = 3;
  std::size_t evaluations_per_start = 200;
  double lower = -20.0, upper = 20.0;
  double start_lower = 0.0, start_upper = 1.0;
  bool warm_start = true;
};

struct ParameterFitResult {
  std::vector<double> parameters;
  double error = worst_error;
  std::size_t evaluations = 0;
};

template <class T>
ParameterFitResult fit_parameters(const Program& program, std::span<const std::vector<ConstantSlot>> parameter_slots,
                                  BatchInterpreter<T>& interpreter, const ParameterFitOptions& options,
                                  const RandomStream& random, std::span<const double> previous = {});

}  // namespace pbrfit::gp
