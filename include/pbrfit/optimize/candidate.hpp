#pragma once
// A point with its objective value and the tolerance that value was computed at.
//
// Invariant: value is never NaN (the evaluator reports NaN as +inf); an unevaluated candidate has
// value +inf.
#include <limits>
#include <vector>

namespace pbrfit::optimize {

struct Candidate {
  std::vector<double> x;
  double value = std::numeric_limits<double>::infinity();
  double tolerance = 0.0;
};

}  // namespace pbrfit::optimize
