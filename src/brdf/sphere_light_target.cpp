#include "pbrfit/brdf/sphere_light_target.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/integrate/compensated_sum.hpp"
#include "pbrfit/integrate/gauss_kronrod.hpp"
#include "pbrfit/integrate/lp_term.hpp"

namespace pbrfit::brdf {
namespace {

namespace gk = integrate::gauss_kronrod;

struct RuleNode {
  double x;
  double weight;
};

// The 15-point Kronrod rule on `panels` equal panels of [lo, hi].
std::vector<RuleNode> composite_rule(double lo, double hi, int panels) {
  std::vector<RuleNode> rule;
  const double width = (hi - lo) / panels;
  for (int p = 0; p < panels; ++p) {
    const double centre = lo + (p + 0.5) * width;
    for (int i = 0; i < gk::kronrod_size; ++i) {
      rule.push_back({centre + 0.5 * width * gk::kronrod_nodes[i], 0.5 * width * gk::kronrod_weights[i]});
    }
  }
  return rule;
}

}  // namespace

SphereLightTarget::SphereLightTarget(double alpha, const SphereLight& light, const ViewGrid& grid,
                                     const integrate::AdaptiveOptions& options)
    : alpha_(alpha), light_(light) {
  const Frame frame = Frame::from_z(mirror_about_normal(light.centre));
  const double scale = alpha + light.radius();
  const auto radial = composite_rule(0.0, 1.0, std::max(1, grid.radial_panels));
  const auto azimuth = composite_rule(0.0, 2.0 * std::numbers::pi, std::max(1, grid.azimuth_panels));
  for (const RuleNode& t : radial) {
    const double u = scale * t.x / (1.0 - t.x);
    const double theta = 2.0 * std::atan(u);
    const double d_theta = 2.0 / (1.0 + u * u) * scale / ((1.0 - t.x) * (1.0 - t.x));
    for (const RuleNode& phi : azimuth) {
      Node node;
      const double sin_theta = std::sin(theta);
      node.view = frame.from_local(Vector3(sin_theta * std::cos(phi.x), sin_theta * std::sin(phi.x),
                                                std::cos(theta)));
      node.weight = t.weight * d_theta * sin_theta * phi.weight;
      if (node.view.z() > 0.0) {
        const SphereLightResponse response = sphere_light_response(alpha, light, node.view, options);
        node.truth = response.value;
        largest_error_estimate_ = std::max(largest_error_estimate_, response.error_estimate);
        evaluations_ += response.evaluations;
        converged_ = converged_ && response.converged;
      }
      nodes_.push_back(node);
    }
  }
}

double SphereLightTarget::error(const std::function<double(const Vector3&)>& model, double p) const {
  if (std::isinf(p)) {
    double largest = 0.0;
    for (const Node& node : nodes_) largest = std::max(largest, std::abs(node.truth - model(node.view)));
    return largest;
  }
  integrate::CompensatedSum sum;
  for (const Node& node : nodes_) sum.add(node.weight * integrate::lp_term(node.truth - model(node.view), p));
  return p == 2.0 ? std::sqrt(sum.value()) : std::pow(sum.value(), 1.0 / p);
}

double SphereLightTarget::norm(double p) const {
  return error([](const Vector3&) { return 0.0; }, p);
}

double SphereLightTarget::least_squares_scale(const std::function<double(const Vector3&)>& model) const {
  integrate::CompensatedSum cross, square;
  for (const Node& node : nodes_) {
    const double value = model(node.view);
    cross.add(node.weight * node.truth * value);
    square.add(node.weight * value * value);
  }
  return square.value() > 0.0 ? cross.value() / square.value() : 0.0;
}

}  // namespace pbrfit::brdf
