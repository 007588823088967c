#pragma once
// Fitting a full 3 x 3 LTC to a set of directions, as the eBRDF prefiltering of Nahmias 2022 (section 3.4,
// after Kt et al. 2022) does with the samples of an effective BRDF: minimize the sliced Wasserstein distance
// (sliced_wasserstein.hpp) over M up to scale, from the moment-matched start M0 (moment_matching.hpp), with
// the optimize engine's Nelder-Mead with restarts. The search runs over the eight entries of P other than
// P22 in M = M0 (I + P), P22 = 0 fixing the scale, each in [-3, 3].
//
// The amplitude is not a shape parameter of the samples: the caller's estimate (the eBRDF's albedo) is passed
// through to the result.
//
// Contract: deterministic; evaluations <= max_evaluations; `distance` is SW at `matrix` on the fit's own
// axes and base samples, and never exceeds `start_distance`, SW at M0.
#include <cstddef>
#include <span>

#include "pbrfit/geometry/vector.hpp"
#include "pbrfit/optimize/nelder_mead.hpp"
#include "pbrfit/optimize/stop_reason.hpp"

namespace pbrfit::ltc {

optimize::NelderMeadOptions default_anisotropic_search();

struct AnisotropicFitOptions {
  std::size_t axes = 32;
  std::size_t max_evaluations = 4000;
  optimize::NelderMeadOptions search = default_anisotropic_search();
};

struct AnisotropicFit {
  Matrix3 matrix = Matrix3::Identity();
  double amplitude = 1.0;
  double distance = 0.0;
  double start_distance = 0.0;
  std::size_t evaluations = 0;
  optimize::StopReason stop = optimize::StopReason::budget;
};

AnisotropicFit fit_ltc_to_samples(std::span<const Vector3> targets, double amplitude,
                                  const AnisotropicFitOptions& options);

// The same search from the better (by SW) of the moment-matched start and `warm_start` (an invertible
// matrix, typically a neighbouring view's fit); `start_distance` is SW at the start used.
AnisotropicFit fit_ltc_to_samples(std::span<const Vector3> targets, double amplitude, const Matrix3& warm_start,
                                  const AnisotropicFitOptions& options);

}  // namespace pbrfit::ltc
