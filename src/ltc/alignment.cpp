#include "pbrfit/ltc/alignment.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace pbrfit::ltc {
namespace {

const Matrix3 flip_y = Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();
constexpr int scan_angles = 72;
constexpr int refinement_steps = 48;

// Mean squared distance between normalize(m s) and the reference directions.
double sample_distance(const Matrix3& m, std::span<const Vector3> base, const std::vector<Vector3>& reference) {
  double sum = 0.0;
  for (std::size_t k = 0; k < base.size(); ++k) sum += ((m * base[k]).normalized() - reference[k]).squaredNorm();
  return sum / static_cast<double>(base.size());
}

// The angle in [phi - step, phi + step] minimizing cost, by golden-section search.
template <class Cost>
double refine_angle(const Cost& cost, double phi, double step) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double low = phi - step;
  double high = phi + step;
  double left = high - ratio * (high - low);
  double right = low + ratio * (high - low);
  double left_cost = cost(left);
  double right_cost = cost(right);
  for (int i = 0; i < refinement_steps; ++i) {
    if (left_cost <= right_cost) {
      high = right;
      right = left;
      right_cost = left_cost;
      left = high - ratio * (high - low);
      left_cost = cost(left);
    } else {
      low = left;
      left = right;
      left_cost = right_cost;
      right = low + ratio * (high - low);
      right_cost = cost(right);
    }
  }
  return 0.5 * (low + high);
}

}  // namespace

Matrix3 rotation_about_z(double phi) {
  Matrix3 r;
  r << std::cos(phi), -std::sin(phi), 0.0,  //
      std::sin(phi), std::cos(phi), 0.0,    //
      0.0, 0.0, 1.0;
  return r;
}

Matrix3 align_to_matrix(const Matrix3& m, const Matrix3& reference) {
  const Matrix3 target = reference / reference.norm();
  Matrix3 best = m;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const Matrix3& flip : {Matrix3(Matrix3::Identity()), flip_y}) {
    const Matrix3 flipped = m * flip;
    const Matrix3 a = (flipped / m.norm()).transpose() * target;
    const Matrix3 candidate = flipped * rotation_about_z(std::atan2(a(1, 0) - a(0, 1), a(0, 0) + a(1, 1)));
    const double cost = (candidate / m.norm() - target).squaredNorm();
    if (cost < best_cost) {
      best_cost = cost;
      best = candidate;
    }
  }
  return best;
}

Matrix3 align_to_samples(const Matrix3& m, const Matrix3& reference, std::span<const Vector3> base_samples) {
  std::vector<Vector3> reference_directions;
  reference_directions.reserve(base_samples.size());
  for (const Vector3& s : base_samples) reference_directions.push_back((reference * s).normalized());
  const double step = 2.0 * std::numbers::pi / scan_angles;
  Matrix3 best = m;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const Matrix3& flip : {Matrix3(Matrix3::Identity()), flip_y}) {
    const Matrix3 flipped = m * flip;
    const auto cost = [&](double phi) {
      return sample_distance(flipped * rotation_about_z(phi), base_samples, reference_directions);
    };
    int best_index = 0;
    double best_scan = std::numeric_limits<double>::infinity();
    for (int j = 0; j < scan_angles; ++j) {
      const double value = cost(j * step);
      if (value < best_scan) {
        best_scan = value;
        best_index = j;
      }
    }
    const double refined = refine_angle(cost, best_index * step, step);
    const double phi = cost(refined) < best_scan ? refined : best_index * step;
    const double value = cost(phi);
    if (value < best_cost) {
      best_cost = value;
      best = flipped * rotation_about_z(phi);
    }
  }
  return best;
}

}  // namespace pbrfit::ltc
