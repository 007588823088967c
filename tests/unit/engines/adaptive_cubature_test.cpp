#include <catch2/catch_test_macros.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <utility>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/integrate/adaptive_cubature.hpp"

using pbrfit::integrate::AdaptiveOptions;
using pbrfit::integrate::AdaptiveResult;
using pbrfit::integrate::Box;
using pbrfit::integrate::integrate_adaptive;

namespace {

template <int Dim>
Box<Dim> unit_box() {
  Box<Dim> box;
  box.hi.fill(1.0);
  return box;
}

template <int Dim, int Comp, class F>
AdaptiveResult<Comp> integrate_on(const F& f, const Box<Dim>& box, const AdaptiveOptions& options) {
  return integrate_adaptive<Dim, Comp>(f, std::span<const Box<Dim>>(&box, 1), options);
}

// A random polynomial of the given degree with coefficients in [-1, 1).
struct Polynomial {
  std::vector<double> coefficients;

  Polynomial(int degree, std::uint64_t item) {
    pbrfit::RandomStream random(42, item);
    for (int k = 0; k <= degree; ++k) coefficients.push_back(2.0 * random.uniform() - 1.0);
  }
  double operator()(double x) const {
    double value = 0.0;
    for (auto it = coefficients.rbegin(); it != coefficients.rend(); ++it) value = value * x + *it;
    return value;
  }
  double integral(double lo, double hi) const {
    double sum = 0.0;
    for (std::size_t k = 0; k < coefficients.size(); ++k) {
      sum += coefficients[k] * (std::pow(hi, k + 1.0) - std::pow(lo, k + 1.0)) / (k + 1.0);
    }
    return sum;
  }
};

template <int Dim>
void check_separable_polynomial_on_one_tile(int degree) {
  std::array<Polynomial, Dim> factors = [&]<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<Polynomial, Dim>{Polynomial(degree, I)...};
  }(std::make_index_sequence<Dim>{});
  Box<Dim> box;
  double exact = 1.0;
  for (int d = 0; d < Dim; ++d) {
    box.lo[d] = -0.5 - 0.25 * d;
    box.hi[d] = 1.0 + 0.5 * d;
    exact *= factors[d].integral(box.lo[d], box.hi[d]);
  }
  const auto f = [&](const std::array<double, Dim>& x) {
    double product = 1.0;
    for (int d = 0; d < Dim; ++d) product *= factors[d](x[d]);
    return std::array<double, 1>{product};
  };
  AdaptiveOptions one_tile;
  one_tile.max_evaluations = 1;  // the initial tile is always evaluated, nothing more
  const auto result = integrate_on<Dim, 1>(f, box, one_tile);
  CAPTURE(Dim, degree, result.value[0], exact);
  CHECK(result.tiles == 1);
  CHECK(std::abs(result.value[0] - exact) <= 1e-13 * (1.0 + std::abs(exact)));
}

}  // namespace

TEST_CASE("Polynomials of degree <= 23 per dimension are exact on one tile") {
  for (int degree : {0, 5, 13, 23}) {
    check_separable_polynomial_on_one_tile<1>(degree);
    check_separable_polynomial_on_one_tile<2>(degree);
    check_separable_polynomial_on_one_tile<3>(degree);
  }
}

TEST_CASE("Polynomials of degree <= 13 converge on the first tile (Gauss is exact too)") {
  const Polynomial p(13, 7);
  const auto f = [&](const std::array<double, 2>& x) { return std::array<double, 1>{p(x[0]) * p(x[1])}; };
  AdaptiveOptions options;
  options.abs_tolerance = 1e-12;
  const auto result = integrate_on<2, 1>(f, unit_box<2>(), options);
  CHECK(result.converged);
  CHECK(result.tiles == 1);
  CHECK(result.evaluations == 225);
  const double exact = p.integral(0.0, 1.0) * p.integral(0.0, 1.0);
  CHECK(std::abs(result.value[0] - exact) < 1e-14);
}

TEST_CASE("Smooth integrands reach 1e-10 in 1, 2 and 3 dimensions, within the error estimate") {
  AdaptiveOptions options;
  options.abs_tolerance = 1e-11;

  SECTION("1-D: exp and an oscillation, two components") {
    const auto f = [](const std::array<double, 1>& x) {
      return std::array<double, 2>{std::exp(x[0]), std::cos(20.0 * x[0])};
    };
    Box<1> box{{-1.0}, {2.0}};
    const auto result = integrate_on<1, 2>(f, box, options);
    const double exact_exp = std::exp(2.0) - std::exp(-1.0);
    const double exact_cos = (std::sin(40.0) - std::sin(-20.0)) / 20.0;
    REQUIRE(result.converged);
    CHECK(result.tiles > 1);
    CHECK(std::abs(result.value[0] - exact_exp) < 1e-10);
    CHECK(std::abs(result.value[1] - exact_cos) < 1e-10);
    CHECK(std::abs(result.value[0] - exact_exp) <= result.error_estimate);
    CHECK(std::abs(result.value[1] - exact_cos) <= result.error_estimate);
  }
  SECTION("2-D: cos(3x) cos(5y) exp(x y)") {
    const auto f = [](const std::array<double, 2>& x) {
      return std::array<double, 1>{std::cos(7.0 * x[0]) * std::cos(11.0 * x[1])};
    };
    const auto result = integrate_on<2, 1>(f, unit_box<2>(), options);
    const double exact = std::sin(7.0) / 7.0 * std::sin(11.0) / 11.0;
    REQUIRE(result.converged);
    CHECK(std::abs(result.value[0] - exact) < 1e-10);
    CHECK(std::abs(result.value[0] - exact) <= result.error_estimate);
  }
  SECTION("3-D: exp(x + 2y + 3z) on a box") {
    const auto f = [](const std::array<double, 3>& x) {
      return std::array<double, 1>{std::exp(x[0] + 2.0 * x[1] + 3.0 * x[2])};
    };
    const auto result = integrate_on<3, 1>(f, unit_box<3>(), options);
    const double exact = std::expm1(1.0) * std::expm1(2.0) / 2.0 * std::expm1(3.0) / 3.0;
    REQUIRE(result.converged);
    CHECK(std::abs(result.value[0] - exact) < 1e-10);
    CHECK(std::abs(result.value[0] - exact) <= result.error_estimate);
  }
  SECTION("3-D: a Gaussian bump that needs refinement") {
    const auto f = [](const std::array<double, 3>& x) {
      const double r2 = (x[0] - 0.3) * (x[0] - 0.3) + (x[1] - 0.6) * (x[1] - 0.6) + (x[2] - 0.5) * (x[2] - 0.5);
      return std::array<double, 1>{std::exp(-40.0 * r2)};
    };
    const auto result = integrate_on<3, 1>(f, unit_box<3>(), options);
    const auto axis = [](double c) {
      return std::sqrt(std::numbers::pi / 40.0) / 2.0 * (std::erf(std::sqrt(40.0) * (1.0 - c)) + std::erf(std::sqrt(40.0) * c));
    };
    const double exact = axis(0.3) * axis(0.6) * axis(0.5);
    REQUIRE(result.converged);
    CHECK(result.tiles > 1);
    CHECK(std::abs(result.value[0] - exact) < 1e-10);
    CHECK(std::abs(result.value[0] - exact) <= result.error_estimate);
  }
}

TEST_CASE("A kink converges by refining around it") {
  const auto f = [](const std::array<double, 1>& x) { return std::array<double, 1>{std::abs(x[0] - 1.0 / 3.0)}; };
  const double exact = (1.0 / 9.0 + 4.0 / 9.0) / 2.0;
  std::size_t previous_tiles = 0;
  double previous_error = 1.0;
  for (double tolerance : {1e-4, 1e-7, 1e-10}) {
    AdaptiveOptions options;
    options.abs_tolerance = tolerance;
    const auto result = integrate_on<1, 1>(f, unit_box<1>(), options);
    CAPTURE(tolerance, result.tiles);
    REQUIRE(result.converged);
    CHECK(result.tiles > previous_tiles);
    const double error = std::abs(result.value[0] - exact);
    CHECK(error <= result.error_estimate);
    CHECK(error <= previous_error);
    previous_tiles = result.tiles;
    previous_error = error;
  }
}

TEST_CASE("Tiles split along the axis that carries the variation") {
  AdaptiveOptions options;
  options.abs_tolerance = 1e-9;
  const auto kink_1d = [](const std::array<double, 1>& x) { return std::array<double, 1>{std::abs(x[0] - 0.3)}; };
  const auto kink_in_y = [](const std::array<double, 2>& x) { return std::array<double, 1>{std::abs(x[1] - 0.3)}; };
  const auto result_1d = integrate_on<1, 1>(kink_1d, unit_box<1>(), options);
  const auto result_2d = integrate_on<2, 1>(kink_in_y, unit_box<2>(), options);
  REQUIRE(result_1d.converged);
  REQUIRE(result_2d.converged);
  CHECK(result_2d.tiles == result_1d.tiles);  // no split was wasted on x
  CHECK(std::abs(result_2d.value[0] - result_1d.value[0]) < 1e-12);
}

TEST_CASE("Results are bitwise reproducible") {
  const auto f = [](const std::array<double, 2>& x) {
    return std::array<double, 2>{std::sqrt(x[0] + x[1]), std::sin(9.0 * x[0] * x[1])};
  };
  const std::array<Box<2>, 2> tiles = {Box<2>{{0.0, 0.0}, {0.5, 1.0}}, Box<2>{{0.5, 0.0}, {1.0, 1.0}}};
  AdaptiveOptions options;
  options.abs_tolerance = 1e-10;
  const auto first = integrate_adaptive<2, 2>(f, std::span<const Box<2>>(tiles), options);
  const auto second = integrate_adaptive<2, 2>(f, std::span<const Box<2>>(tiles), options);
  CHECK(std::memcmp(first.value.data(), second.value.data(), sizeof(first.value)) == 0);
  CHECK(std::memcmp(&first.error_estimate, &second.error_estimate, sizeof(double)) == 0);
  CHECK(first.evaluations == second.evaluations);
  CHECK(first.tiles == second.tiles);
  CHECK(first.converged == second.converged);
}

TEST_CASE("max_evaluations stops the refinement unconverged") {
  const auto step = [](const std::array<double, 2>& x) { return std::array<double, 1>{x[0] + x[1] < 0.7 ? 1.0 : 0.0}; };
  AdaptiveOptions options;
  options.abs_tolerance = 1e-12;
  options.max_evaluations = 225 * 21;
  const auto result = integrate_on<2, 1>(step, unit_box<2>(), options);
  CHECK_FALSE(result.converged);
  CHECK(result.evaluations <= options.max_evaluations);
  CHECK(result.evaluations == 225 * 21);  // 1 initial tile + 10 splits
  CHECK(result.tiles == 11);
  CHECK(result.error_estimate > options.abs_tolerance);
  CHECK(std::abs(result.value[0] - 0.245) < 0.05);
}

TEST_CASE("max_depth retires tiles whose error still counts") {
  const auto step = [](const std::array<double, 1>& x) { return std::array<double, 1>{x[0] < 1.0 / 3.0 ? 1.0 : 0.0}; };
  AdaptiveOptions options;
  options.abs_tolerance = 1e-12;
  options.max_depth = 6;
  const auto result = integrate_on<1, 1>(step, unit_box<1>(), options);
  CHECK_FALSE(result.converged);
  CHECK(result.error_estimate > options.abs_tolerance);
  CHECK(result.tiles <= 64);
  CHECK(result.evaluations == 15 * (2 * result.tiles - 1));  // a binary tree of evaluated tiles
  CHECK(std::abs(result.value[0] - 1.0 / 3.0) <= result.error_estimate);
}

TEST_CASE("Several initial tiles, empty input and non-finite samples") {
  const auto f = [](const std::array<double, 1>& x) { return std::array<double, 1>{x[0] * x[0]}; };
  SECTION("initial tiles add up") {
    const std::array<Box<1>, 3> tiles = {Box<1>{{0.0}, {1.0}}, Box<1>{{1.0}, {2.0}}, Box<1>{{2.0}, {3.0}}};
    const auto result = integrate_adaptive<1, 1>(f, std::span<const Box<1>>(tiles), AdaptiveOptions{});
    CHECK(result.converged);
    CHECK(result.tiles == 3);
    CHECK(std::abs(result.value[0] - 9.0) < 1e-13);
  }
  SECTION("no tiles: zero, converged") {
    const auto result = integrate_adaptive<1, 1>(f, std::span<const Box<1>>(), AdaptiveOptions{});
    CHECK(result.converged);
    CHECK(result.value[0] == 0.0);
    CHECK(result.evaluations == 0);
  }
  SECTION("a NaN sample never converges and still terminates") {
    const auto bad = [](const std::array<double, 1>& x) {
      return std::array<double, 1>{x[0] > 0.5 ? std::nan("") : 1.0};
    };
    AdaptiveOptions options;
    options.max_evaluations = 15 * 41;
    const auto result = integrate_on<1, 1>(bad, unit_box<1>(), options);
    CHECK_FALSE(result.converged);
    CHECK(result.evaluations <= options.max_evaluations);
  }
}

namespace {

// An integrand with the optional bind_outer fast path; counts how often each path is used.
template <int Dim>
struct BindableIntegrand {
  int* binds;
  int* plain_calls;

  struct Slice {
    double cos_x0;
    std::array<double, 1> operator()(const std::array<double, Dim>& x) const {
      double rest = 0.0;
      for (int d = 1; d < Dim; ++d) rest += x[d] * x[d];
      return {cos_x0 * std::exp(-rest)};
    }
  };
  Slice bind_outer(double x0) const {
    ++*binds;
    return Slice{std::cos(3.0 * x0)};
  }
  std::array<double, 1> operator()(const std::array<double, Dim>& x) const {
    ++*plain_calls;
    return Slice{std::cos(3.0 * x[0])}(x);
  }
};

template <int Dim>
void check_binding_changes_nothing() {
  int binds = 0;
  int plain_calls = 0;
  const BindableIntegrand<Dim> bindable{&binds, &plain_calls};
  const auto plain = [](const std::array<double, Dim>& x) {
    double rest = 0.0;
    for (int d = 1; d < Dim; ++d) rest += x[d] * x[d];
    return std::array<double, 1>{std::cos(3.0 * x[0]) * std::exp(-rest)};
  };
  AdaptiveOptions options;
  options.abs_tolerance = 1e-12;
  const auto fast = integrate_on<Dim, 1>(bindable, unit_box<Dim>(), options);
  const auto slow = integrate_on<Dim, 1>(plain, unit_box<Dim>(), options);
  CAPTURE(Dim);
  CHECK(plain_calls == 0);
  std::size_t slice_points = 1;
  for (int d = 1; d < Dim; ++d) slice_points *= 15;
  CHECK(static_cast<std::size_t>(binds) * slice_points == fast.evaluations);
  CHECK(fast.value[0] == slow.value[0]);
  CHECK(fast.evaluations == slow.evaluations);
}

}  // namespace

TEST_CASE("bind_outer is used once per first coordinate and changes nothing") {
  check_binding_changes_nothing<2>();
  check_binding_changes_nothing<3>();
}
