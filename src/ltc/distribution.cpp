#include "pbrfit/ltc/distribution.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ltc_batch.hpp"
#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/ltc/polygon_integral.hpp"
#include "polygon_clipping.hpp"

namespace pbrfit::ltc {

LtcDistribution::LtcDistribution(const Matrix3& m, double amplitude) : m_(m), amplitude_(amplitude) {
  const double determinant = m.determinant();
  if (!m.allFinite() || !std::isfinite(determinant) || determinant == 0.0) {
    throw std::invalid_argument("ltc: the matrix of an LTC must be finite and invertible");
  }
  if (!(amplitude >= 0.0) || !std::isfinite(amplitude)) throw std::invalid_argument("ltc: amplitude must be >= 0");
  m_inverse_ = m.inverse();
  inverse_determinant_ = std::abs(1.0 / determinant);
}

double LtcDistribution::pdf(const Vector3& w) const {
  const Vector3 original = m_inverse_ * w;
  const double length_squared = original.squaredNorm();
  const double cosine = std::max(0.0, original.z());
  return cosine * inverse_determinant_ * std::numbers::inv_pi / (length_squared * length_squared);
}

Vector3 LtcDistribution::sample(double u1, double u2) const {
  return (m_ * sample_clamped_cosine(u1, u2)).normalized();
}

LtcDistribution::Transformed LtcDistribution::transform(const Vector3& base) const {
  const Vector3 image = m_ * base;
  const double length = image.norm();
  // |M^-1 w| = 1 / |M s| for w = M s / |M s| and a unit s.
  const double pdf = base.z() * std::numbers::inv_pi * inverse_determinant_ * length * length * length;
  return {image / length, pdf};
}

namespace {

detail::LtcConstants constants_of(const Matrix3& m, const Matrix3& inverse, double inverse_determinant) {
  detail::LtcConstants c{};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) {
      c.m[3 * r + k] = m(r, k);
      c.inverse[3 * r + k] = inverse(r, k);
    }
  c.inverse_determinant = inverse_determinant;
  return c;
}

}  // namespace

void LtcDistribution::transform_many(std::span<const Vector3> base, std::span<Vector3> direction,
                                     std::span<double> pdf) const {
  if (base.empty()) return;
  detail::ltc_batch(active_kernel_set())
      .transform(constants_of(m_, m_inverse_, inverse_determinant_), base.data(), base.size(), direction.data(),
                 pdf.data());
}

void LtcDistribution::pdf_many(std::span<const Vector3> w, std::span<double> pdf) const {
  if (w.empty()) return;
  detail::ltc_batch(active_kernel_set())
      .pdf(constants_of(m_, m_inverse_, inverse_determinant_), w.data(), w.size(), pdf.data());
}

double LtcDistribution::integrate_polygon(std::span<const Vector3> vertices) const {
  if (vertices.size() < 3) throw std::invalid_argument("ltc: a polygon needs at least 3 vertices");
  const auto transformed = [&](std::size_t i) -> Vector3 { return m_inverse_ * vertices[i]; };
  return amplitude_ * detail::clipped_clamped_cosine_integral(vertices.size(), transformed);
}

}  // namespace pbrfit::ltc
