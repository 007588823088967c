#include "pbrfit/ltc/fit_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/ltc/point_sets.hpp"

namespace pbrfit::ltc {

FitErrorEstimator::FitErrorEstimator(std::shared_ptr<const brdf::Lobe> target, std::size_t points)
    : target_(std::move(target)) {
  if (!target_) throw std::invalid_argument("ltc: a fit error needs a target lobe");
  target_samples_.reserve(points);
  base_.reserve(points);
  for (const auto& [u1, u2] : golden_lattice(points)) {
    const Vector3 l = target_->sample(u1, u2);
    const brdf::Lobe::Evaluation evaluation = target_->evaluate(l);
    target_samples_.push_back({l, evaluation.value, evaluation.pdf});
    base_.push_back(sample_clamped_cosine(u1, u2));
  }
  double squared = 0.0;
  for (const TargetSample& sample : target_samples_)
    if (sample.pdf > 0.0) squared += sample.value * sample.value / sample.pdf;
  target_l2_ = points > 0 ? std::sqrt(squared / static_cast<double>(points)) : 0.0;
}

// Calls accumulate(difference, pdf_target + pdf_ltc) once per sample of each strategy, in order. The
// LTC's samples reach the target in groups, through Lobe::evaluate_many (vector code where the lobe has it).
template <class Accumulate>
void FitErrorEstimator::visit(const LtcDistribution& ltc, Accumulate&& accumulate) const {
  const double amplitude = ltc.amplitude();
  constexpr std::size_t group = 64;
  std::array<Vector3, group> directions;
  std::array<double, group> ltc_pdf;
  std::array<brdf::Lobe::Evaluation, group> target;
  for (std::size_t first = 0; first < base_.size(); first += group) {
    const std::size_t n = std::min(group, base_.size() - first);
    for (std::size_t i = 0; i < n; ++i) {
      const LtcDistribution::Transformed sample = ltc.transform(base_[first + i]);
      directions[i] = sample.direction;
      ltc_pdf[i] = sample.pdf;
    }
    target_->evaluate_many({directions.data(), n}, {target.data(), n});
    for (std::size_t i = 0; i < n; ++i)
      accumulate(target[i].value - amplitude * ltc_pdf[i], target[i].pdf + ltc_pdf[i]);
  }
  for (const TargetSample& sample : target_samples_) {
    const double pdf = ltc.pdf(sample.direction);
    accumulate(sample.value - amplitude * pdf, sample.pdf + pdf);
  }
}

double FitErrorEstimator::cubed_error(const LtcDistribution& ltc) const {
  double sum = 0.0;
  visit(ltc, [&](double difference, double pdf) {
    const double magnitude = std::abs(difference);
    if (pdf > 0.0) sum += magnitude * magnitude * magnitude / pdf;
  });
  return sum / static_cast<double>(points());
}

FitError FitErrorEstimator::errors(const LtcDistribution& ltc) const {
  double cubed = 0.0;
  double squared = 0.0;
  visit(ltc, [&](double difference, double pdf) {
    if (!(pdf > 0.0)) return;
    const double magnitude = std::abs(difference);
    cubed += magnitude * magnitude * magnitude / pdf;
    squared += magnitude * magnitude / pdf;
  });
  const double count = static_cast<double>(points());
  return {cubed / count, std::sqrt(squared / count), target_l2_};
}

}  // namespace pbrfit::ltc
