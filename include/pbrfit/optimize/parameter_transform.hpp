#pragma once
// How one model parameter maps to the optimizer's internal coordinate (Pesce & Iwanicki 2015, section
// 7.6: solvers behave better when every coordinate has the same order of magnitude and changes at a
// similar rate). A parameter with bounds [lower, upper] maps increasingly onto the internal [0, 1]:
//   linear  u = (p - lower) / (upper - lower)
//   log     u = log(p / lower) / log(upper / lower)           scale-like parameters; needs 0 < lower
//   cosine  u = (cos lower - cos p) / (cos lower - cos upper)  angles in radians, 0 <= lower, upper <= pi;
//                                                             u is uniform in cos(angle)
// Invariants: from_internal(to_internal(p)) equals p up to rounding for p in [lower, upper];
// to_internal maps p <= lower (or NaN) to 0 and p >= upper to 1; from_internal clamps u into [0, 1] and
// returns a value in [lower, upper]; a fixed parameter (lower == upper) maps to u = 0 and back to lower.
#include <string>

namespace pbrfit::optimize {

enum class Transform { linear, log, cosine };

struct Parameter {
  std::string name;
  double lower = 0.0;
  double upper = 1.0;
  Transform transform = Transform::linear;
};

// Why the parameter cannot be searched ("parameter 'x' needs ..."): non-finite or inverted bounds, or bounds
// outside the transform's domain; empty when it can.
std::string invalid_reason(const Parameter& parameter);
// Throws std::invalid_argument("optimize: " + the reason) when there is one.
void validate(const Parameter& parameter);

double to_internal(const Parameter& parameter, double value);
double from_internal(const Parameter& parameter, double internal);

}  // namespace pbrfit::optimize
