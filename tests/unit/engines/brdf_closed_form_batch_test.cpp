#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "kernel_set_scope.hpp"
#include "pbrfit/brdf/beckmann.hpp"
#include "pbrfit/brdf/brdf_families.hpp"
#include "pbrfit/brdf/sheen.hpp"
#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/core/random_stream.hpp"

using pbrfit::RandomStream;
using pbrfit::Vector3;
using pbrfit::brdf::BeckmannView;
using pbrfit::brdf::BrdfFamily;
using pbrfit::brdf::CharlieView;

namespace {

// Charlie's rho written out from Estevez & Kulla with std::pow and std::exp, independent of sheen.cpp.
double charlie_reference(double alpha, const Vector3& v, const Vector3& l) {
  if (!(v.z() > 0.0) || !(l.z() > 0.0)) return 0.0;
  const double smooth[5] = {25.3245, 3.32435, 0.16801, -1.27393, -4.85967};
  const double rough[5] = {21.5473, 3.82987, 0.19823, -1.97760, -4.32054};
  const double w = (1.0 - alpha) * (1.0 - alpha);
  double p[5];
  for (int i = 0; i < 5; ++i) p[i] = (1.0 - w) * rough[i] + w * smooth[i];
  const auto big_l = [&](double x) { return p[0] / (1.0 + p[1] * std::pow(x, p[2])) + p[3] * x + p[4]; };
  const auto lambda = [&](double mu) {
    return mu < 0.5 ? std::exp(big_l(mu)) : std::exp(2.0 * big_l(0.5) - big_l(1.0 - mu));
  };
  const double cos_h = (v + l).normalized().z();
  const double sin_h = std::sqrt(std::max(0.0, 1.0 - cos_h * cos_h));
  const double d = (2.0 + 1.0 / alpha) * std::pow(sin_h, 1.0 / alpha) / (2.0 * std::numbers::pi);
  return d / (4.0 * v.z() * (1.0 + lambda(v.z()) + lambda(l.z())));
}

// Beckmann's rho from the scalar distribution and Smith Lambda (std::exp, std::erfc).
double beckmann_reference(double alpha, const Vector3& v, const Vector3& l) {
  using namespace pbrfit::brdf;
  if (!(v.z() > 0.0) || !(l.z() > 0.0) || (v + l).norm() == 0.0) return 0.0;
  const double masking = 1.0 / (1.0 + beckmann_smith_lambda(alpha, v.z()) + beckmann_smith_lambda(alpha, l.z()));
  return beckmann_distribution(alpha, (v + l).normalized().z()) * masking / (4.0 * v.z());
}

std::vector<Vector3> test_directions(RandomStream& random, const Vector3& v) {
  std::vector<Vector3> directions;
  for (int i = 0; i < 997; ++i) {  // not a multiple of the 16 lanes: a padded last group
    const double z = 2.0 * random.uniform() - 1.0;
    const double phi = 2.0 * std::numbers::pi * random.uniform();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    directions.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  directions.push_back(-v);                                     // l = -v: h undefined
  directions.emplace_back(-v.x(), -v.y(), v.z());               // the mirror direction: h = n
  directions.emplace_back(1.0, 0.0, 0.0);                       // on the horizon
  directions.emplace_back(std::sqrt(1.0 - 1e-20), 0.0, 1e-10);  // just above it
  directions.emplace_back(0.0, 0.0, 1.0);                       // the normal
  directions.emplace_back(std::sqrt(0.75), 0.0, 0.5);           // where Charlie's Lambda branches meet
  return directions;
}

// A view's rho through many() in every kernel set: the same alone (operator()) and at any place among
// others, and within 1e-12 of the reference; returns the values of the last set.
template <class View>
std::vector<double> check_view(const View& rho, const std::vector<Vector3>& directions,
                               const std::function<double(const Vector3&)>& reference, const std::string& what) {
  std::vector<double> batch(directions.size());
  for (const pbrfit::KernelSet set : pbrfit::kernel_sets_available()) {
    const kernel_test::KernelSetScope scope(set);
    std::vector<double> shifted(directions.size() + 5);
    rho.many(directions.data(), directions.size(), batch.data());
    std::vector<Vector3> later(5, Vector3(0.0, 0.6, 0.8));
    later.insert(later.end(), directions.begin(), directions.end());
    rho.many(later.data(), later.size(), shifted.data());
    std::size_t differing = 0, moved = 0, far = 0;
    for (std::size_t i = 0; i < directions.size(); ++i) {
      const double alone = rho(directions[i]);
      if (std::memcmp(&alone, &batch[i], sizeof alone) != 0) ++differing;
      if (std::memcmp(&batch[i], &shifted[i + 5], sizeof alone) != 0) ++moved;
      const double expected = reference(directions[i]);
      if (!(std::abs(batch[i] - expected) <= 1e-12 * expected + 1e-300)) ++far;
    }
    CAPTURE(what, pbrfit::kernel_set_name(set));
    CHECK(differing == 0);
    CHECK(moved == 0);
    CHECK(far == 0);
    const std::size_t last = directions.size();
    CHECK(batch[last - 6] == 0.0);  // l = -v
    CHECK(batch[last - 4] == 0.0);  // the horizon
  }
  return batch;
}

Vector3 view_at(double cos_theta_view) {
  return {std::sqrt(1.0 - cos_theta_view * cos_theta_view), 0.0, cos_theta_view};
}

}  // namespace

// CharlieView and BeckmannView evaluate rho as vector code (src/brdf/closed_form_batch.hpp).
TEST_CASE("Charlie's and Beckmann's vector rho: the same alone and in groups, near the scalar form", "[brdf]") {
  RandomStream random(2026, 12, 7);
  for (const double alpha : {1e-3, 0.09, 0.49, 1.0}) {
    for (const double cos_theta_view : {1.0, 0.7, 0.05}) {
      const Vector3 v = view_at(cos_theta_view);
      const auto directions = test_directions(random, v);
      const std::string where = "alpha " + std::to_string(alpha) + ", cos theta_v " + std::to_string(cos_theta_view);
      const auto charlie = check_view(CharlieView(alpha, v), directions,
                                      [&](const Vector3& l) { return charlie_reference(alpha, v, l); }, "charlie, " + where);
      CHECK(charlie[directions.size() - 5] == 0.0);  // h = n: no sheen
      check_view(BeckmannView(alpha, v), directions,
                 [&](const Vector3& l) { return beckmann_reference(alpha, v, l); }, "beckmann, " + where);
    }
  }
}

TEST_CASE("The Charlie and Beckmann family lobes evaluate many directions as they evaluate one", "[brdf]") {
  RandomStream random(7, 12);
  for (const BrdfFamily family : {BrdfFamily::charlie, BrdfFamily::beckmann}) {
    const auto lobe = pbrfit::brdf::make_family_lobe(family, 0.4, 0.6);
    const auto directions = test_directions(random, lobe->view());
    std::vector<pbrfit::brdf::Lobe::Evaluation> many(directions.size());
    std::vector<double> values(directions.size());
    lobe->evaluate_many(directions, many);
    lobe->value_many(directions, values);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < directions.size(); ++i) {
      const auto one = lobe->evaluate(directions[i]);
      if (std::memcmp(&one.value, &many[i].value, sizeof(double)) != 0 ||
          std::memcmp(&one.pdf, &many[i].pdf, sizeof(double)) != 0 ||
          std::memcmp(&one.value, &values[i], sizeof(double)) != 0)
        ++differing;
    }
    CAPTURE(pbrfit::brdf::family_info(family).name);
    CHECK(differing == 0);
  }
}
