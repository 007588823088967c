#pragma once
// Test support: Monte Carlo estimates of the split-sum DFG terms, independent of the quadrature's
// mapping. Light directions come either from h ~ D(h)(n.h) over the full azimuth range (reflected
// about h) or uniformly from the hemisphere; f, D and V come from the public brdf functions only.
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "pbrfit/brdf/ggx.hpp"
#include "pbrfit/core/random_stream.hpp"

namespace pbrfit::test {

enum class LightSampling { ggx_half_vector, uniform_hemisphere };

struct Estimate {
  double mean = 0.0;
  double standard_error = 0.0;
};

struct DfgEstimate {
  Estimate scale;
  Estimate bias;
};

using Vector = std::array<double, 3>;

inline double dot(const Vector& a, const Vector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Accumulates mean and standard error of the mean of a weight sequence.
class MomentAccumulator {
 public:
  void add(double x) {
    sum_ += x;
    sum_squares_ += x * x;
    ++count_;
  }
  Estimate estimate() const {
    const double mean = sum_ / count_;
    const double variance = std::max(0.0, sum_squares_ / count_ - mean * mean);
    return {mean, std::sqrt(variance / (count_ - 1))};
  }

 private:
  double sum_ = 0.0;
  double sum_squares_ = 0.0;
  long count_ = 0;
};

// A light direction and its pdf with respect to solid angle.
struct LightSample {
  Vector l;
  double pdf;
};

inline LightSample sample_light(LightSampling sampling, const Vector& v, double alpha, RandomStream& random) {
  const double phi = 2.0 * std::numbers::pi * random.uniform();
  const double xi = random.uniform();
  if (sampling == LightSampling::uniform_hemisphere) {
    const double cos_theta = xi;
    const double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);
    return {{sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta}, 1.0 / (2.0 * std::numbers::pi)};
  }
  const double tan_squared = alpha * alpha * xi / (1.0 - xi);  // inverse CDF of D(h)(n.h) in theta
  const double cos_theta = 1.0 / std::sqrt(1.0 + tan_squared);
  const double sin_theta = std::sqrt(tan_squared) * cos_theta;
  const Vector h{sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
  const double v_dot_h = dot(v, h);
  const Vector l{2.0 * v_dot_h * h[0] - v[0], 2.0 * v_dot_h * h[1] - v[1], 2.0 * v_dot_h * h[2] - v[2]};
  const double pdf = v_dot_h > 0.0 ? brdf::ggx_distribution(alpha, cos_theta) * cos_theta / (4.0 * v_dot_h) : 0.0;
  return {l, pdf};
}

// The weight f (n.l) / pdf(l) of one light sample, split into its (1 - Fc) and Fc parts.
inline std::array<double, 2> dfg_weights(const Vector& v, double alpha, brdf::SmithVisibility visibility,
                                         const LightSample& sample) {
  const double n_dot_l = sample.l[2];
  if (!(n_dot_l > 0.0 && sample.pdf > 0.0)) return {0.0, 0.0};
  const Vector sum{v[0] + sample.l[0], v[1] + sample.l[1], v[2] + sample.l[2]};
  const double length = std::sqrt(dot(sum, sum));
  const Vector h{sum[0] / length, sum[1] / length, sum[2] / length};
  const double f = brdf::ggx_distribution(alpha, h[2]) * brdf::smith_visibility(visibility, alpha, v[2], n_dot_l);
  const double weight = f * n_dot_l / sample.pdf;
  const double fresnel = std::pow(1.0 - dot(v, h), 5.0);
  return {weight * (1.0 - fresnel), weight * fresnel};
}

inline Vector view_direction(double n_dot_v) { return {std::sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v}; }

inline DfgEstimate monte_carlo_dfg(double n_dot_v, double alpha, brdf::SmithVisibility visibility,
                                   LightSampling sampling, long samples, std::uint64_t item) {
  RandomStream random(2024, item);
  const Vector v = view_direction(n_dot_v);
  MomentAccumulator scale;
  MomentAccumulator bias;
  for (long i = 0; i < samples; ++i) {
    const auto weights = dfg_weights(v, alpha, visibility, sample_light(sampling, v, alpha, random));
    scale.add(weights[0]);
    bias.add(weights[1]);
  }
  return {scale.estimate(), bias.estimate()};
}

// E_avg = 2 int_0^1 E(mu) mu dmu: mu is drawn with density 2 mu, then one GGX half-vector light sample.
inline Estimate monte_carlo_average_albedo(double alpha, brdf::SmithVisibility visibility, long samples,
                                           std::uint64_t item) {
  RandomStream random(2025, item);
  MomentAccumulator albedo;
  for (long i = 0; i < samples; ++i) {
    const Vector v = view_direction(std::sqrt(random.uniform()));
    const auto weights = dfg_weights(v, alpha, visibility, sample_light(LightSampling::ggx_half_vector, v, alpha, random));
    albedo.add(weights[0] + weights[1]);
  }
  return albedo.estimate();
}

}  // namespace pbrfit::test
