#pragma once
// How far an LTC is from a target lobe rho (brdf/lobe.hpp), over the whole sphere (Heitz et al. 2016, section 4.1):
//   cubed = integral of |D(l) - rho(l)|^3 dl     (the paper's fitting objective, not its cube root)
//   l2    = sqrt(integral of (D(l) - rho(l))^2 dl)
//   target_l2 = sqrt(integral of rho(l)^2 dl), the target's own L2 norm (l2 / target_l2 is scale-free: 0 for
//               an exact fit, 1 for an LTC of zero amplitude), from the target's samples alone
// estimated by multiple importance sampling of both distributions with the balance heuristic: `points`
// directions drawn from the target and `points` drawn from the LTC, each sum term divided by
// pdf_target + pdf_ltc. One golden lattice (point_sets.hpp) drives both strategies, and the LTC's samples
// are normalize(M s) for fixed cosine samples s, so the estimate is a deterministic function of M,
// continuous wherever it is finite.
//
// Invariants: the target's samples, values and densities are computed once, by the constructor (or drawn by
// sample_lobe and handed to it, lobe_samples.hpp: the same values); an estimate
// allocates nothing and depends only on (target, points, LTC); both errors are >= 0.
#include <cstddef>
#include <memory>
#include <vector>

#include "pbrfit/brdf/lobe.hpp"
#include "pbrfit/geometry/vector.hpp"
#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/lobe_samples.hpp"

namespace pbrfit::ltc {

struct FitError {
  double cubed = 0.0;
  double l2 = 0.0;
  double target_l2 = 0.0;
};

class FitErrorEstimator {
 public:
  FitErrorEstimator(std::shared_ptr<const brdf::Lobe> target, std::size_t points);
  // The same from the target's samples (sample_lobe(*target, points)), already drawn.
  FitErrorEstimator(std::shared_ptr<const brdf::Lobe> target, LobeSamples target_samples);

  double cubed_error(const LtcDistribution& ltc) const;
  FitError errors(const LtcDistribution& ltc) const;
  std::size_t points() const { return base_.size(); }
  double target_l2() const { return target_l2_; }

 private:
  template <class Accumulate>
  void visit(const LtcDistribution& ltc, Accumulate&& accumulate) const;

  std::shared_ptr<const brdf::Lobe> target_;
  // The target's samples: directions, rho and the target's density there.
  std::vector<Vector3> target_directions_;
  std::vector<double> target_values_, target_pdfs_;
  std::vector<Vector3> base_;  // cosine samples the LTC transforms
  double target_l2_ = 0.0;
};

}  // namespace pbrfit::ltc
