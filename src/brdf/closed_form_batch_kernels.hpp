// The closed-form lobes' batch kernels (closed_form_batch.hpp) of one kernel set. Included once by each
// closed_form_batch_isa_<set>.cpp, inside a namespace named by PBRFIT_KERNEL_ISA, so that the sets' copies
// never meet at link time.
#ifndef PBRFIT_KERNEL_ISA
#error "closed_form_batch_kernels.hpp is included by the closed_form_batch_isa_<set>.cpp files only"
#endif
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "closed_form_batch.hpp"
#include "pbrfit/geometry/kernel_lanes.hpp"

namespace pbrfit::brdf::detail::PBRFIT_KERNEL_ISA {

namespace {

// Groups of W lanes: 16 (kernel_lanes.hpp) for many directions, 2 for one direction alone. Eigen's exp and
// log run the same operations on a packet of 2 as on a packet of 8 (the same polynomial, FMA wherever the set
// has it), and division and sqrt are exact, so a direction's value is the same in either; unit tests hold
// one direction alone to the same direction among many, bit for bit, in every set.
constexpr int wide = kernel_lanes::lane_count;
constexpr int narrow = 2;
template <int W>
using Lanes = kernel_lanes::LanesOf<W>;
template <int W>
using Directions = kernel_lanes::DirectionsOf<W>;
using kernel_lanes::gather;
using kernel_lanes::square_root;

// Each transcendental below is assigned to lanes of its own: inside a select() Eigen 3.4 would evaluate it
// one coefficient at a time, through the scalar std::exp and std::log.

// exp(x), 0 where the result would fall below the smallest normal double: Eigen's exp stops at about
// 5e-309 there (for -inf too), where std::exp goes on through the subnormals to 0.
template <int W>
Lanes<W> exponential(const Lanes<W>& x) {
  const Lanes<W> value = x.exp();
  return (x < std::log(std::numeric_limits<double>::min())).select(0.0, value);
}

// x^p for x >= 0 and p > 0 as exp(p log x), 0 at x = 0.
template <int W>
Lanes<W> power(const Lanes<W>& x, double p) {
  const Lanes<W> logarithm = x.log();
  return exponential<W>(p * logarithm);
}

// The z of h = normalize(v + l), as |v + l| = sqrt((x^2 + y^2) + z^2) like Eigen's norm of a 3-vector; NaN
// for l = -v.
template <int W, class Constants>
Lanes<W> half_vector_z(const Constants& view, const Directions<W>& l) {
  const Lanes<W> sum_x = view.view_x + l.x;
  const Lanes<W> sum_y = view.view_y + l.y;
  const Lanes<W> sum_z = view.view_z + l.z;
  return sum_z / square_root<W>(sum_x * sum_x + sum_y * sum_y + sum_z * sum_z);
}

// Up to W directions; lanes past n repeat the last direction and are not stored.
template <int W>
void charlie_group(const CharlieConstants& view, const Vector3* l, std::size_t n, double* out) {
  const Directions<W> d = gather<W>(l, n);
  // D(h) = (2 + 1/alpha) sin^(1/alpha) theta_h / (2 pi), sin^2 theta_h = 1 - (n.h)^2.
  const Lanes<W> n_dot_h = half_vector_z(view, d);
  const Lanes<W> sin_squared = (1.0 - n_dot_h * n_dot_h).max(0.0);
  const Lanes<W> distribution =
      (2.0 + view.inverse_alpha) * power(sin_squared, 0.5 * view.inverse_alpha) / (2.0 * std::numbers::pi);
  // Lambda(mu) = exp(L(mu)) below 1/2, exp(2 L(1/2) - L(1 - mu)) above; L(t) = a / (1 + b t^c) + d t + e.
  const auto low = d.z < 0.5;
  const Lanes<W> t = low.select(d.z, 1.0 - d.z).max(0.0);
  const Lanes<W> l_of_t = view.fit[0] / (1.0 + view.fit[1] * power(t, view.fit[2])) + view.fit[3] * t + view.fit[4];
  const Lanes<W> exponent = low.select(l_of_t, 2.0 * view.l_half - l_of_t);
  const Lanes<W> lambda = exponent.exp();
  const Lanes<W> value = distribution / (4.0 * view.view_z * (1.0 + view.view_lambda + lambda));
  const Lanes<W> kept = (d.z > 0.0).select(value, 0.0);  // also drops l = -v, whose h is undefined
  for (std::size_t i = 0; i < n; ++i) out[i] = kept[i];
}

template <int W>
void beckmann_group(const BeckmannConstants& view, const Vector3* l, std::size_t n, double* out) {
  const Directions<W> d = gather<W>(l, n);
  const double alpha_squared = view.alpha * view.alpha;
  // D(h) = exp(-tan^2 theta_h / alpha^2) / (pi alpha^2 cos^4 theta_h), 0 for n.h <= 0.
  const Lanes<W> n_dot_h = half_vector_z(view, d);
  const Lanes<W> cos_squared = n_dot_h * n_dot_h;
  const Lanes<W> tan_squared = (1.0 - cos_squared) / cos_squared;
  const Lanes<W> falloff = exponential<W>(-tan_squared / alpha_squared);
  const Lanes<W> distribution =
      (n_dot_h > 0.0).select(falloff / (std::numbers::pi * alpha_squared * cos_squared * cos_squared), 0.0);
  // Lambda(l) = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, a = n.l / (alpha sqrt(1 - (n.l)^2)); 0 at n.l >= 1
  // and for a > 26, where both terms underflow.
  const Lanes<W> a = d.z / (view.alpha * square_root<W>(1.0 - d.z * d.z));
  const Lanes<W> minus_a_squared = -a * a;
  const Lanes<W> gaussian = minus_a_squared.exp();
  // erfc once per direction: lanes past n hold copies of the last one (one direction alone costs one call).
  Lanes<W> complement;
  for (std::size_t i = 0; i < n; ++i) complement[i] = a[i] <= 26.0 ? std::erfc(a[i]) : 0.0;
  for (std::size_t i = n; i < W; ++i) complement[i] = complement[n - 1];
  const Lanes<W> tail = 0.5 * (gaussian / (a * std::sqrt(std::numbers::pi)) - complement);
  const Lanes<W> lambda = (d.z >= 1.0 || a > 26.0).select(0.0, tail);
  const Lanes<W> masking = 1.0 / (1.0 + view.view_lambda + lambda);
  const Lanes<W> value = distribution * masking / (4.0 * view.view_z);
  const Lanes<W> kept = (d.z > 0.0).select(value, 0.0);  // l = -v: n.h is NaN, so D is 0 already
  for (std::size_t i = 0; i < n; ++i) out[i] = kept[i];
}

}  // namespace

[[gnu::flatten]] void charlie_batch(const CharlieConstants& view, const Vector3* l, std::size_t n, double* out) {
  if (n == 1) return charlie_group<narrow>(view, l, n, out);
  for (std::size_t first = 0; first < n; first += wide)
    charlie_group<wide>(view, l + first, std::min<std::size_t>(wide, n - first), out + first);
}

[[gnu::flatten]] void beckmann_batch(const BeckmannConstants& view, const Vector3* l, std::size_t n, double* out) {
  if (n == 1) return beckmann_group<narrow>(view, l, n, out);
  for (std::size_t first = 0; first < n; first += wide)
    beckmann_group<wide>(view, l + first, std::min<std::size_t>(wide, n - first), out + first);
}

}  // namespace pbrfit::brdf::detail::PBRFIT_KERNEL_ISA
