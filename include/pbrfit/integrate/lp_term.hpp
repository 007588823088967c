#pragma once
// One term of an L^p distance, |d|^p, with the common norms as plain arithmetic: p = 1 gives |d| and p = 2
// gives d * d exactly, where libm's pow costs far more (a fifth of a sphere-light sweep) and may round the
// last bit differently. Other p go through std::pow.
#include <cmath>

namespace pbrfit::integrate {

inline double lp_term(double difference, double p) {
  const double magnitude = std::abs(difference);
  return p == 1.0 ? magnitude : p == 2.0 ? magnitude * magnitude : std::pow(magnitude, p);
}

}  // namespace pbrfit::integrate
