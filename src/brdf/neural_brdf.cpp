#include "pbrfit/brdf/neural_brdf.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pbrfit::brdf {
namespace {

constexpr std::size_t inputs = 6, hidden = 21, outputs = 3;

// out = relu?(in W + b) for a row-major kernel of in.size() x out.size().
template <std::size_t In, std::size_t Out>
std::array<double, Out> dense(const std::array<double, In>& in, const std::vector<double>& w,
                              const std::vector<double>& b, bool relu) {
  std::array<double, Out> out;
  for (std::size_t j = 0; j < Out; ++j) {
    double sum = b[j];
    for (std::size_t i = 0; i < In; ++i) sum += in[i] * w[i * Out + j];
    out[j] = relu ? std::max(sum, 0.0) : sum;
  }
  return out;
}

}  // namespace

NeuralBrdf::NeuralBrdf(NeuralBrdfWeights weights) : w_(std::move(weights)) {
  if (w_.w1.size() != inputs * hidden || w_.b1.size() != hidden || w_.w2.size() != hidden * hidden ||
      w_.b2.size() != hidden || w_.w3.size() != hidden * outputs || w_.b3.size() != outputs)
    throw std::invalid_argument("neural BRDF: the weights do not have the shapes 6x21, 21x21, 21x3");
}

std::array<double, 3> NeuralBrdf::evaluate(const HalfDiff& a) const {
  const std::array<double, inputs> x = {std::sin(a.theta_h), 0.0, std::cos(a.theta_h),
                                        std::sin(a.theta_d) * std::cos(a.phi_d),
                                        std::sin(a.theta_d) * std::sin(a.phi_d), std::cos(a.theta_d)};
  const auto h1 = dense<inputs, hidden>(x, w_.w1, w_.b1, true);
  const auto h2 = dense<hidden, hidden>(h1, w_.w2, w_.b2, true);
  const auto y = dense<hidden, outputs>(h2, w_.w3, w_.b3, false);
  return {std::max(std::expm1(y[0]), 0.0), std::max(std::expm1(y[1]), 0.0), std::max(std::expm1(y[2]), 0.0)};
}

MerlTable NeuralBrdf::tabulate() const {
  MerlTable table;
  for (std::size_t c = 0; c < merl_cells; ++c) {
    const auto rgb = evaluate(merl_centre_of(merl_cell_at(c)));
    for (std::size_t k = 0; k < 3; ++k) table.set(k, c, rgb[k]);
  }
  return table;
}

}  // namespace pbrfit::brdf
