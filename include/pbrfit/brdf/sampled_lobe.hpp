#pragma once
// A lobe (lobe.hpp) given by a closed-form cosine-weighted BRDF for one view (a callable rho(l) that has
// computed what depends on the view alone once, such as BeckmannView) and one of three standard ways of
// drawing directions (DirectionSampler):
//   cosine       pdf = max(n.l, 0) / pi                 (diffuse lobes)
//   uniform      pdf = 1 / (2 pi) above the horizon     (grazing sheen and cloth lobes)
//   ggx_visible  GGX visible normals of width alpha reflected about v, pdf = G1(v) D(h) / (4 n.v) on the
//                whole sphere (ggx_lobe.hpp; a proposal with wider tails than Beckmann-like lobes)
// The proposal need not be the lobe's own distribution; it only has to cover it (pdf > 0 wherever rho > 0).
//
// A Rho with a member many(l, n, out) (out[i] = rho(l[i]), as CharlieView's vector code) is called with
// whole groups of directions by value_many() and evaluate_many(); it must give rho(l) the same value alone.
//
// Invariants: as Lobe; evaluate(l).value = rho(l).
#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

#include "pbrfit/brdf/lobe.hpp"

namespace pbrfit::brdf {

enum class DirectionSampling { cosine, uniform, ggx_visible };

// pdf and sample of the cosine and uniform hemispheres (0 below the horizon).
double cosine_hemisphere_pdf(const Vector3& l);
Vector3 sample_cosine_hemisphere(double u1, double u2);
double uniform_hemisphere_pdf(const Vector3& l);
Vector3 sample_uniform_hemisphere(double u1, double u2);

// One of the three strategies for a view v (v.z > 0); alpha: the GGX width of ggx_visible (> 0, else
// std::invalid_argument), ignored otherwise.
class DirectionSampler {
 public:
  DirectionSampler(DirectionSampling sampling, double alpha, const Vector3& view);
  double pdf(const Vector3& l) const;
  Vector3 sample(double u1, double u2) const;

 private:
  DirectionSampling sampling_;
  double alpha_;
  Vector3 view_;
  double view_masking_ = 1.0;  // G1(v) of ggx_visible sampling
};

template <class Rho>
class SampledLobe final : public Lobe {
 public:
  SampledLobe(double cos_theta_view, Rho rho, DirectionSampling sampling, double sampling_alpha = 1.0)
      : Lobe(cos_theta_view), rho_(std::move(rho)), sampler_(sampling, sampling_alpha, view()) {}

  Evaluation evaluate(const Vector3& l) const override { return {rho_(l), sampler_.pdf(l)}; }
  Vector3 sample(double u1, double u2) const override { return sampler_.sample(u1, u2); }
  double value(const Vector3& l) const override { return rho_(l); }

  void value_many(std::span<const Vector3> l, std::span<double> out) const override {
    if constexpr (batched) rho_.many(l.data(), l.size(), out.data());
    else Lobe::value_many(l, out);
  }

  void evaluate_many(std::span<const Vector3> l, std::span<Evaluation> out) const override {
    if constexpr (batched) {
      std::array<double, 64> values;
      for (std::size_t first = 0; first < l.size(); first += values.size()) {
        const std::size_t n = std::min(values.size(), l.size() - first);
        rho_.many(l.data() + first, n, values.data());
        for (std::size_t i = 0; i < n; ++i) out[first + i] = {values[i], sampler_.pdf(l[first + i])};
      }
    } else {
      Lobe::evaluate_many(l, out);
    }
  }

 private:
  static constexpr bool batched = requires(const Rho& rho, const Vector3* l, double* out) { rho.many(l, 1, out); };

  Rho rho_;
  DirectionSampler sampler_;
};

}  // namespace pbrfit::brdf
