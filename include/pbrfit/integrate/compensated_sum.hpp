#pragma once
// Neumaier (improved Kahan-Babuska) compensated summation.
//
// Invariant: value() equals the exact sum of the added terms up to one rounding of the result,
// as long as the running sum has no catastrophic overflow; the order of add() calls is the only
// thing the result depends on.
#include <cmath>

namespace pbrfit::integrate {

class CompensatedSum {
 public:
  void add(double term) {
    const double next = sum_ + term;
    if (std::abs(sum_) >= std::abs(term)) {
      compensation_ += (sum_ - next) + term;
    } else {
      compensation_ += (term - next) + sum_;
    }
    sum_ = next;
  }

  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;  // accumulated low-order bits lost by sum_
};

}  // namespace pbrfit::integrate
