#include <catch2/catch_test_macros.hpp>

#include <cmath>

#include "pbrfit/integrate/gauss_kronrod.hpp"

namespace gk = pbrfit::integrate::gauss_kronrod;

namespace {

// Integral of x^k over [-1, 1].
double monomial_integral(int k) { return k % 2 == 0 ? 2.0 / (k + 1) : 0.0; }

double kronrod_monomial(int k) {
  double sum = 0.0;
  for (int i = 0; i < gk::kronrod_size; ++i) sum += gk::kronrod_weights[i] * std::pow(gk::kronrod_nodes[i], k);
  return sum;
}

double gauss_monomial(int k) {
  double sum = 0.0;
  for (int g = 0; g < gk::gauss_size; ++g) {
    sum += gk::gauss_weights[g] * std::pow(gk::kronrod_nodes[gk::gauss_node_position(g)], k);
  }
  return sum;
}

}  // namespace

TEST_CASE("Gauss-Kronrod 7-15 nodes are ascending, symmetric and inside (-1, 1)") {
  for (int i = 0; i < gk::kronrod_size; ++i) {
    CHECK(std::abs(gk::kronrod_nodes[i]) < 1.0);
    CHECK(gk::kronrod_nodes[i] == -gk::kronrod_nodes[gk::kronrod_size - 1 - i]);
    CHECK(gk::kronrod_weights[i] == gk::kronrod_weights[gk::kronrod_size - 1 - i]);
    if (i > 0) CHECK(gk::kronrod_nodes[i - 1] < gk::kronrod_nodes[i]);
  }
  for (int g = 0; g < gk::gauss_size; ++g) CHECK(gk::gauss_weights[g] == gk::gauss_weights[gk::gauss_size - 1 - g]);
}

TEST_CASE("Kronrod 15 is exact to degree 23, Gauss 7 to degree 13") {
  for (int k = 0; k <= 23; ++k) {
    CAPTURE(k);
    CHECK(std::abs(kronrod_monomial(k) - monomial_integral(k)) < 1e-15);
  }
  for (int k = 0; k <= 13; ++k) {
    CAPTURE(k);
    CHECK(std::abs(gauss_monomial(k) - monomial_integral(k)) < 1e-15);
  }
  // Exactness stops where theory says, which also checks that the Gauss subset is the nested one.
  CHECK(std::abs(gauss_monomial(14) - monomial_integral(14)) > 1e-5);
  CHECK(std::abs(kronrod_monomial(24) - monomial_integral(24)) > 1e-10);
}

TEST_CASE("Gauss nodes are the roots of the Legendre polynomial P7") {
  for (int g = 0; g < gk::gauss_size; ++g) {
    const double x = gk::kronrod_nodes[gk::gauss_node_position(g)];
    // P7(x) = (429 x^7 - 693 x^5 + 315 x^3 - 35 x) / 16
    const double x2 = x * x;
    const double p7 = x * (((429.0 * x2 - 693.0) * x2 + 315.0) * x2 - 35.0) / 16.0;
    CAPTURE(g, x);
    CHECK(std::abs(p7) < 1e-14);
  }
}
