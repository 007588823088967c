#include "pbrfit/brdf/tabulated_lobe.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pbrfit/brdf/sampled_lobe.hpp"
#include "pbrfit/core/bin_index.hpp"

namespace pbrfit::brdf {
namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

double checked(double value) {
  if (!std::isfinite(value) || value < 0.0)
    throw std::invalid_argument("brdf: a tabulated lobe's value is negative or not finite");
  return value;
}

// The direction where rho is largest among the mirror direction, the view, the normal and the centres of an
// equal-area 32 x 64 grid of the upper hemisphere (the first of equal maxima).
Vector3 peak_direction(const Vector3& view, const TabulatedLobe::Function& rho) {
  Vector3 best = Vector3(-view.x(), -view.y(), view.z());
  double best_value = checked(rho(best));
  const auto consider = [&](const Vector3& l) {
    const double value = checked(rho(l));
    if (value > best_value) best_value = value, best = l;
  };
  consider(view);
  consider(Vector3::UnitZ());
  constexpr int rings = 32, sectors = 64;
  for (int i = 0; i < rings; ++i) {
    const double z = 1.0 - (i + 0.5) / rings;
    const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int j = 0; j < sectors; ++j) {
      const double phi = two_pi * (j + 0.5) / sectors;
      consider(Vector3(radius * std::cos(phi), radius * std::sin(phi), z));
    }
  }
  return best.normalized();
}

Vector3 polar_direction(double cos_theta, double phi) {
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

}  // namespace

TabulatedLobe::TabulatedLobe(double cos_theta_view, Function rho, const TabulationOptions& options)
    : Lobe(cos_theta_view), rho_(std::move(rho)), options_(options) {
  if (options.polar_bins < 1 || options.azimuth_bins < 1 || !(options.cosine_share > 0.0 && options.cosine_share <= 1.0))
    throw std::invalid_argument("brdf: a tabulated lobe needs bins and a cosine share in (0, 1]");
  frame_ = Frame::from_z(peak_direction(view(), rho_));
  const std::size_t rings = options.polar_bins, sectors = options.azimuth_bins;
  ring_cosines_.resize(rings + 1);
  for (std::size_t i = 0; i <= rings; ++i) {
    const double t = double(i) / double(rings);
    ring_cosines_[i] = std::cos(std::numbers::pi * t * t);
  }
  ring_cosines_.back() = -1.0;
  // rho at the corners of every cell (sectors wrap around) and at the centres.
  std::vector<double> corners((rings + 1) * sectors);
  for (std::size_t i = 0; i <= rings; ++i)
    for (std::size_t j = 0; j < sectors; ++j)
      corners[i * sectors + j] =
          checked(rho_(frame_.from_local(polar_direction(ring_cosines_[i], two_pi * double(j) / double(sectors)))));
  std::vector<double> weight(rings * sectors);
  double total = 0.0;
  const double sector_angle = two_pi / double(sectors);
  for (std::size_t i = 0; i < rings; ++i) {
    const double solid_angle = (ring_cosines_[i] - ring_cosines_[i + 1]) * sector_angle;
    const double centre_cos = 0.5 * (ring_cosines_[i] + ring_cosines_[i + 1]);
    for (std::size_t j = 0; j < sectors; ++j) {
      const std::size_t next = (j + 1) % sectors;
      const double centre =
          checked(rho_(frame_.from_local(polar_direction(centre_cos, sector_angle * (double(j) + 0.5)))));
      const double corner_sum = corners[i * sectors + j] + corners[i * sectors + next] +
                                corners[(i + 1) * sectors + j] + corners[(i + 1) * sectors + next];
      weight[i * sectors + j] = solid_angle * (corner_sum + 4.0 * centre) / 8.0;
      total += weight[i * sectors + j];
    }
  }
  cosine_share_ = total > 0.0 ? options.cosine_share : 1.0;
  cumulative_.resize(weight.size());
  density_.resize(weight.size());
  double running = 0.0;
  for (std::size_t i = 0; i < rings; ++i) {
    const double solid_angle = (ring_cosines_[i] - ring_cosines_[i + 1]) * sector_angle;
    for (std::size_t j = 0; j < sectors; ++j) {
      const std::size_t cell = i * sectors + j;
      const double probability = total > 0.0 ? weight[cell] / total : 0.0;
      running += probability;
      cumulative_[cell] = running;
      density_[cell] = solid_angle > 0.0 ? probability / solid_angle : 0.0;
      if (probability > 0.0) last_cell_ = cell;
    }
  }
}

std::size_t TabulatedLobe::cell_of(const Vector3& local) const {
  const double theta = std::acos(std::clamp(local.z(), -1.0, 1.0));
  const std::size_t ring = bin_index(std::sqrt(theta / std::numbers::pi), options_.polar_bins);
  double phi = std::atan2(local.y(), local.x());
  if (phi < 0.0) phi += two_pi;
  const std::size_t sector = bin_index(phi / two_pi, options_.azimuth_bins);
  return ring * options_.azimuth_bins + sector;
}

double TabulatedLobe::pdf(const Vector3& l) const {
  double tabulated = 0.0;
  if (cosine_share_ < 1.0) tabulated = density_[cell_of(frame_.to_local(l))];
  return cosine_share_ * cosine_hemisphere_pdf(l) + (1.0 - cosine_share_) * tabulated;
}

TabulatedLobe::Evaluation TabulatedLobe::evaluate(const Vector3& l) const { return {rho_(l), pdf(l)}; }

Vector3 TabulatedLobe::sample(double u1, double u2) const {
  if (u1 < cosine_share_) return sample_cosine_hemisphere(u1 / cosine_share_, u2);
  const double u = (u1 - cosine_share_) / (1.0 - cosine_share_);
  // The first cell whose cumulative probability exceeds u: never one of probability 0 (u rounded up to the
  // total falls back to the last cell that has any).
  const auto found = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
  const std::size_t cell = found == cumulative_.end() ? last_cell_ : std::size_t(found - cumulative_.begin());
  const double below = cell == 0 ? 0.0 : cumulative_[cell - 1];
  const double width = cumulative_[cell] - below;
  const double f = width > 0.0 ? std::clamp((u - below) / width, 0.0, 1.0) : 0.5;
  const std::size_t ring = cell / options_.azimuth_bins, sector = cell % options_.azimuth_bins;
  const double cos_theta = ring_cosines_[ring] + f * (ring_cosines_[ring + 1] - ring_cosines_[ring]);
  const double phi = two_pi * (double(sector) + u2) / double(options_.azimuth_bins);
  return frame_.from_local(polar_direction(cos_theta, phi)).normalized();
}

}  // namespace pbrfit::brdf
