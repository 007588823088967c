#pragma once
// A BRDF lobe seen from one view: the cosine-weighted BRDF rho(l) = f(v, l) max(n . l, 0) for a fixed view
// v = (sin theta_v, 0, cos theta_v) in the x-z plane of the shading frame (n = +z), with F = 1, together with
// a way of drawing directions l and the density of that drawing. This is what an LTC table approximates per
// cell (ltc/), what its moments and errors are estimated with, and what polygon lights are integrated over.
//
// Contract of every lobe:
//  - evaluate(l) is a pure function of l: value = rho(l) >= 0 (0 below the horizon), pdf = the density of
//    sample() at l over the whole sphere (it integrates to 1; it may be > 0 where rho = 0);
//  - pdf > 0 wherever value > 0, so importance-sampled estimates of integrals of rho are unbiased;
//  - sample(u1, u2) returns a unit direction for (u1, u2) in [0, 1)^2 and is deterministic;
//  - value(l) is evaluate(l).value, possibly cheaper; peak() is where rho is largest when the lobe knows it;
//  - evaluate_many(l, out) sets out[i] = evaluate(l[i]) and value_many(l, out) out[i] = value(l[i]), bit for
//    bit, for spans of equal length; a lobe may override them with vector code of the active kernel set
//    (core/kernel_set.hpp): GgxLobe's has arithmetic and sqrt only, which round the same in every set;
//    the Charlie and Beckmann lobes' use vector exp and log, so their values may differ between sets in
//    the last bits (never between one direction and many);
//  - a lobe is immutable once built and may be shared by threads.
#include <optional>
#include <span>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

class Lobe {
 public:
  struct Evaluation {
    double value = 0.0;  // rho(l)
    double pdf = 0.0;    // the density of sample() at l
  };

  virtual ~Lobe() = default;
  const Vector3& view() const { return view_; }
  virtual Evaluation evaluate(const Vector3& l) const = 0;
  virtual void evaluate_many(std::span<const Vector3> l, std::span<Evaluation> out) const;
  virtual Vector3 sample(double u1, double u2) const = 0;
  virtual double value(const Vector3& l) const { return evaluate(l).value; }
  virtual void value_many(std::span<const Vector3> l, std::span<double> out) const;
  virtual std::optional<Vector3> peak() const { return std::nullopt; }

 protected:
  // Throws std::invalid_argument unless 0 < cos theta_v <= 1.
  explicit Lobe(double cos_theta_view);

 private:
  Vector3 view_;
};

// (sin theta_v, 0, cos theta_v) for 0 < cos theta_v <= 1 (std::invalid_argument otherwise).
Vector3 view_in_xz_plane(double cos_theta_view);

}  // namespace pbrfit::brdf
