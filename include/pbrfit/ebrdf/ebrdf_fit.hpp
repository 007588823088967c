#pragma once
// One LTC fitted to one effective BRDF's sample set (Nahmias 2022, section 3.4.1; Kt et al. 2022):
//  - descent (default): gradient descent on the sliced Wasserstein distance (ltc/descent_fit.hpp), from the
//    better of the moment-matched start and an optional warm start (the previous view's fit of the texel);
//  - nelder_mead: the fitting engine's Nelder-Mead on the sliced Wasserstein distance with fixed axes and base samples
//    (ltc/anisotropic_fit.hpp), from the better of the moment-matched start and an optional warm start
//    (the previous view's fit of the same texel);
//  - sgd: the thesis' baseline, stochastic gradient descent from the identity (ltc/sgd_fit.hpp).
// Either way the matrix is then aligned to the representative closest to the cosine's own samples
// (ltc/alignment.hpp, reference = identity, over alignment_samples cosine samples) and scaled to
// |det M| = 1 (an LTC is unchanged by scale).
//
// Contract: `error` is the sliced Wasserstein distance of the stored matrix on error_axes fixed axes and
// the fixed cosine base samples, the same evaluation for both methods, so their errors compare; the
// matrix is row-major; deterministic (sgd draws from the stream it is given).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/ltc/anisotropic_fit.hpp"
#include "pbrfit/ltc/descent_fit.hpp"
#include "pbrfit/ltc/sgd_fit.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ebrdf {

enum class FitMethod { descent, nelder_mead, sgd };

struct EbrdfFitSettings {
  FitMethod method = FitMethod::descent;
  ltc::DescentFitOptions descent;
  ltc::AnisotropicFitOptions search;
  ltc::SgdOptions sgd;
  std::size_t error_axes = 32;
  std::size_t alignment_samples = 32;
};

struct EbrdfFit {
  std::array<double, 9> matrix{};
  double amplitude = 0.0;
  double error = 0.0;
  std::uint32_t evaluations = 0;  // sliced Wasserstein evaluations (sgd: epochs)
  double start_error = 0.0;       // descent, nelder_mead: SW at the start, on the search's axes
};

EbrdfFit fit_ebrdf(std::span<const Vector3> samples, double amplitude, const EbrdfFitSettings& settings,
                   RandomStream& sgd_random, const Matrix3* warm_start = nullptr);

Matrix3 fit_matrix(const EbrdfFit& fit);

// M / cbrt(|det M|).
Matrix3 unit_determinant(const Matrix3& m);

}  // namespace pbrfit::ebrdf
