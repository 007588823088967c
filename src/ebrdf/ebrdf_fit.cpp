#include "pbrfit/ebrdf/ebrdf_fit.hpp"

#include <cmath>

#include "pbrfit/ltc/alignment.hpp"
#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/ltc/sliced_wasserstein.hpp"

namespace pbrfit::ebrdf {

Matrix3 unit_determinant(const Matrix3& m) {
  const double determinant = std::abs(m.determinant());
  if (!(determinant > 0.0) || !std::isfinite(determinant)) return m;
  return m / std::cbrt(determinant);
}

EbrdfFit fit_ebrdf(std::span<const Vector3> samples, double amplitude, const EbrdfFitSettings& settings,
                   RandomStream& sgd_random, const Matrix3* warm_start) {
  EbrdfFit fit;
  Matrix3 m;
  if (settings.method == FitMethod::sgd) {
    m = ltc::sgd_fit_from_identity(samples, settings.sgd, sgd_random);
    fit.evaluations = std::uint32_t(settings.sgd.epochs);
  } else if (settings.method == FitMethod::descent) {
    const ltc::AnisotropicFit search = ltc::fit_ltc_by_descent(samples, amplitude, warm_start, settings.descent);
    m = search.matrix;
    fit.evaluations = std::uint32_t(search.evaluations);
    fit.start_error = search.start_distance;
  } else {
    const ltc::AnisotropicFit search = warm_start
                                           ? ltc::fit_ltc_to_samples(samples, amplitude, *warm_start, settings.search)
                                           : ltc::fit_ltc_to_samples(samples, amplitude, settings.search);
    m = search.matrix;
    fit.evaluations = std::uint32_t(search.evaluations);
    fit.start_error = search.start_distance;
  }
  if (!m.allFinite() || std::abs(m.determinant()) < 1e-300) m = Matrix3::Identity();
  const Matrix3 aligned =
      unit_determinant(ltc::align_to_samples(m, Matrix3::Identity(), ltc::cosine_samples(settings.alignment_samples)));
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) fit.matrix[std::size_t(3 * r + c)] = aligned(r, c);
  fit.amplitude = amplitude;
  fit.error = ltc::SlicedWasserstein(samples, settings.error_axes).distance(aligned);
  return fit;
}

Matrix3 fit_matrix(const EbrdfFit& fit) {
  Matrix3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = fit.matrix[std::size_t(3 * r + c)];
  return m;
}

}  // namespace pbrfit::ebrdf
