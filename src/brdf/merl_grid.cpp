#include "pbrfit/brdf/merl_grid.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pbrfit/core/bin_index.hpp"

namespace pbrfit::brdf {
namespace {

constexpr double half_pi = 0.5 * std::numbers::pi;

}  // namespace

MerlCell merl_cell_of(const HalfDiff& a) {
  double phi_d = a.phi_d;
  if (phi_d < 0.0) phi_d += std::numbers::pi;  // reciprocity
  return {bin_index(std::sqrt(std::max(a.theta_h, 0.0) / half_pi), merl_theta_h),
          bin_index(a.theta_d / half_pi, merl_theta_d), bin_index(phi_d / std::numbers::pi, merl_phi_d)};
}

MerlCell merl_cell_at(std::size_t flat) {
  MerlCell c;
  c.phi_d = flat % merl_phi_d;
  c.theta_d = (flat / merl_phi_d) % merl_theta_d;
  c.theta_h = flat / (merl_phi_d * merl_theta_d);
  return c;
}

HalfDiff merl_centre_of(const MerlCell& c) {
  const double h = (double(c.theta_h) + 0.5) / double(merl_theta_h);
  HalfDiff a;
  a.theta_h = h * h * half_pi;
  a.theta_d = (double(c.theta_d) + 0.5) / double(merl_theta_d) * half_pi;
  a.phi_d = (double(c.phi_d) + 0.5) / double(merl_phi_d) * std::numbers::pi;
  return a;
}

}  // namespace pbrfit::brdf
