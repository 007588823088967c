#include "pbrfit/ltc/moment_matching.hpp"

#include <algorithm>
#include <cmath>

namespace pbrfit::ltc {
namespace {

constexpr double min_scale = 1e-4;
constexpr double max_scale = 1e3;

// The m with isotropic_second_moment(m) = moment, by bisection in ln m (the moment increases with m).
double scale_for_second_moment(double moment) {
  double low = std::log(min_scale);
  double high = std::log(max_scale);
  for (int iteration = 0; iteration < 64; ++iteration) {
    const double middle = 0.5 * (low + high);
    (isotropic_second_moment(std::exp(middle)) < moment ? low : high) = middle;
  }
  return std::exp(0.5 * (low + high));
}

}  // namespace

// E[x^2] = (1/2) integral over u = sin^2 theta in [0, 1] of m^2 u / (m^2 u + 1 - u) du.
double isotropic_second_moment(double m) {
  const double m_squared = m * m;
  const double k = m_squared - 1.0;
  double integral = 0.0;
  if (std::abs(k) < 1e-4) {
    integral = 0.5 - k / 3.0 + k * k / 4.0;  // the series of integral of u / (1 + k u) du
  } else {
    integral = 1.0 / k - std::log(m_squared) / (k * k);
  }
  return 0.5 * m_squared * integral;
}

Matrix3 moment_matched_ltc(std::span<const Vector3> targets) {
  Vector3 mean = Vector3::Zero();
  for (const Vector3& t : targets) mean += t;
  const Frame frame = Frame::from_z(mean.squaredNorm() > 0.0 ? Vector3(mean.normalized()) : Vector3::UnitZ());
  Eigen::Matrix2d second_moment = Eigen::Matrix2d::Zero();
  for (const Vector3& t : targets) {
    const Eigen::Vector2d tangential(t.dot(frame.x), t.dot(frame.y));
    second_moment += tangential * tangential.transpose();
  }
  if (!targets.empty()) second_moment /= static_cast<double>(targets.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> principal(second_moment);
  Matrix3 m;
  for (int axis = 0; axis < 2; ++axis) {
    const Eigen::Vector2d e = principal.eigenvectors().col(axis);
    const double scale = scale_for_second_moment(std::max(0.0, principal.eigenvalues()(axis)));
    m.col(axis) = scale * (e.x() * frame.x + e.y() * frame.y);
  }
  m.col(2) = frame.z;
  return m;
}

}  // namespace pbrfit::ltc
