#include "pbrfit/ltc/fit_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/ltc/point_sets.hpp"

namespace pbrfit::ltc {

FitErrorEstimator::FitErrorEstimator(std::shared_ptr<const brdf::Lobe> target, std::size_t points)
    : FitErrorEstimator(target, target ? sample_lobe(*target, points) : LobeSamples{}) {}

FitErrorEstimator::FitErrorEstimator(std::shared_ptr<const brdf::Lobe> target, LobeSamples target_samples)
    : target_(std::move(target)),
      target_directions_(std::move(target_samples.directions)),
      target_values_(std::move(target_samples.values)),
      target_pdfs_(std::move(target_samples.pdfs)) {
  if (!target_) throw std::invalid_argument("ltc: a fit error needs a target lobe");
  const std::size_t points = target_directions_.size();
  base_.reserve(points);
  for (const auto& [u1, u2] : golden_lattice(points)) base_.push_back(sample_clamped_cosine(u1, u2));
  double squared = 0.0;
  for (std::size_t i = 0; i < points; ++i)
    if (target_pdfs_[i] > 0.0) squared += target_values_[i] * target_values_[i] / target_pdfs_[i];
  target_l2_ = points > 0 ? std::sqrt(squared / static_cast<double>(points)) : 0.0;
}

// Calls accumulate(difference, pdf, n) once per group of up to 64 samples of each strategy, in order, with
// difference[i] = rho - D and pdf[i] = pdf_target + pdf_ltc. Both strategies' samples go through the batch
// members (vector code where the lobe has it, and the LTC's in every kernel set), whose values are those of
// the scalar members bit for bit. A group at a time, so that the caller's sums stay in registers.
template <class Accumulate>
void FitErrorEstimator::visit(const LtcDistribution& ltc, Accumulate&& accumulate) const {
  const double amplitude = ltc.amplitude();
  constexpr std::size_t group = 64;
  std::array<Vector3, group> directions;
  std::array<double, group> ltc_pdf, difference, pdf;
  std::array<brdf::Lobe::Evaluation, group> target;
  for (std::size_t first = 0; first < base_.size(); first += group) {
    const std::size_t n = std::min(group, base_.size() - first);
    ltc.transform_many(std::span(base_).subspan(first, n), std::span(directions.data(), n), std::span(ltc_pdf.data(), n));
    target_->evaluate_many({directions.data(), n}, {target.data(), n});
    for (std::size_t i = 0; i < n; ++i) {
      difference[i] = target[i].value - amplitude * ltc_pdf[i];
      pdf[i] = target[i].pdf + ltc_pdf[i];
    }
    accumulate(difference.data(), pdf.data(), n);
  }
  for (std::size_t first = 0; first < target_directions_.size(); first += group) {
    const std::size_t n = std::min(group, target_directions_.size() - first);
    ltc.pdf_many(std::span(target_directions_).subspan(first, n), std::span(ltc_pdf.data(), n));
    for (std::size_t i = 0; i < n; ++i) {
      difference[i] = target_values_[first + i] - amplitude * ltc_pdf[i];
      pdf[i] = target_pdfs_[first + i] + ltc_pdf[i];
    }
    accumulate(difference.data(), pdf.data(), n);
  }
}

double FitErrorEstimator::cubed_error(const LtcDistribution& ltc) const {
  double sum = 0.0;
  visit(ltc, [&](const double* difference, const double* pdf, std::size_t n) {
    double group_sum = sum;  // summed in the same order as one running sum, but in a register
    for (std::size_t i = 0; i < n; ++i) {
      const double magnitude = std::abs(difference[i]);
      if (pdf[i] > 0.0) group_sum += magnitude * magnitude * magnitude / pdf[i];
    }
    sum = group_sum;
  });
  return sum / static_cast<double>(points());
}

FitError FitErrorEstimator::errors(const LtcDistribution& ltc) const {
  double cubed = 0.0;
  double squared = 0.0;
  visit(ltc, [&](const double* difference, const double* pdf, std::size_t n) {
    double group_cubed = cubed, group_squared = squared;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(pdf[i] > 0.0)) continue;
      const double magnitude = std::abs(difference[i]);
      group_cubed += magnitude * magnitude * magnitude / pdf[i];
      group_squared += magnitude * magnitude / pdf[i];
    }
    cubed = group_cubed;
    squared = group_squared;
  });
  const double count = static_cast<double>(points());
  return {cubed / count, std::sqrt(squared / count), target_l2_};
}

}  // namespace pbrfit::ltc
