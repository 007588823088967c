#include "pbrfit/ebrdf/ggx_ltc_curve.hpp"

#include <algorithm>
#include <cmath>

#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/ltc/isotropic_fit.hpp"

namespace pbrfit::ebrdf {
namespace {

constexpr double min_cosine = 0.01;

double curve_cosine_at(std::size_t i, std::size_t points) {
  const double x = double(i) / double(points - 1);
  return std::max(min_cosine, 1.0 - x * x);
}

}  // namespace

GgxLtcCurve::GgxLtcCurve(double alpha, std::size_t points) {
  ltc::IsotropicParameters start;
  ltc::CellFitOptions options;
  for (std::size_t i = 0; i < std::max<std::size_t>(points, 2); ++i) {
    const double cosine = curve_cosine_at(i, std::max<std::size_t>(points, 2));
    const ltc::CellFit fit = ltc::fit_isotropic_cell(std::make_shared<brdf::GgxLobe>(alpha, cosine), start, options);
    fits_.push_back({fit.matrix, fit.moments.albedo});
    start = fit.parameters;
  }
}

LtcLookup GgxLtcCurve::at(double cos_theta) const {
  const double x = std::sqrt(1.0 - std::clamp(cos_theta, min_cosine, 1.0)) * double(fits_.size() - 1);
  const std::size_t i = std::min(fits_.size() - 2, static_cast<std::size_t>(x));
  const double t = std::min(1.0, x - double(i));
  return {fits_[i].matrix * (1.0 - t) + fits_[i + 1].matrix * t,
          fits_[i].amplitude * (1.0 - t) + fits_[i + 1].amplitude * t};
}

}  // namespace pbrfit::ebrdf
