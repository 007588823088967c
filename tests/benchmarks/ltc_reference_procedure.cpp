// The LTC paper's published fitting procedure (Heitz et al. 2016, the 2017 revision of its reference fitter,
// fitLTC.cpp), written anew on pbrfit's lobes, so that a family's table can be compared with what that
// procedure makes of the same lobe on the same grid (the paper's own code covers GGX, Beckmann and Disney
// diffuse; it is not run here). The procedure, as published:
//   - 64 x 64 texels: roughness r = a / 63 (alpha = max(r^2, 1e-5) for the microfacet families), view
//     x = t / 63 = sqrt(1 - cos theta_v) with theta_v capped at 1.57;
//   - order: a from 63 down to 0, and for each a, t from 0 up to 63; the first texel starts at m11 = m22 = 1,
//     each t = 0 texel from the (a + 1, 0) fit, every other texel from the previous texel's parameters;
//   - M = [X Y Z] [[m11, 0, m13], [0, m22, 0], [0, 0, 1]] with Z the lobe's average direction (identity
//     frame and m22 = m11, m13 = 0 at t = 0), norm and average direction from 32 x 32 midpoint samples of the
//     lobe's own sampling;
//   - error: the cubed difference by MIS of 32 x 32 midpoint samples of the LTC and of the lobe;
//   - Nelder-Mead on (m11, m22, m13): initial simplex steps 0.05, at most 100 iterations, stopping when the
//     simplex's values agree to 1e-5 relative (Numerical Recipes' criterion); m11, m22 clamped at 1e-7.
// Both tables are then judged by pbrfit's estimators (4096 MIS points per strategy, amplitude our albedo).
//
//   bench_ltc_reference FAMILY OURS.csv
// OURS.csv: "view_index roughness_index m00 m11 m02 m20" per texel of the family's pbrfit table (written by
// tests/benchmarks/ltc_families_benchmark.sh from the result file).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

#include "pbrfit/brdf/brdf_families.hpp"
#include "pbrfit/ltc/distribution.hpp"
#include "pbrfit/ltc/isotropic_parameters.hpp"
#include "pbrfit/ltc/isotropic_target.hpp"

using namespace pbrfit;

namespace {

constexpr int size = 64;
constexpr int samples = 32;

double midpoint(int i) { return (i + 0.5) / samples; }

struct Moments {
  double norm = 0.0;
  Vector3 direction = Vector3::UnitZ();
};

Moments midpoint_moments(const brdf::Lobe& lobe) {
  Moments m;
  Vector3 sum = Vector3::Zero();
  for (int j = 0; j < samples; ++j)
    for (int i = 0; i < samples; ++i) {
      const Vector3 l = lobe.sample(midpoint(i), midpoint(j));
      const auto e = lobe.evaluate(l);
      if (!(e.pdf > 0.0)) continue;
      m.norm += e.value / e.pdf;
      sum += e.value / e.pdf * l;
    }
  m.norm /= samples * samples;
  sum.y() = 0.0;
  if (sum.squaredNorm() > 0.0) m.direction = sum.normalized();
  return m;
}

struct Fit {
  std::array<double, 3> p{1.0, 1.0, 0.0};  // m11, m22, m13
  Vector3 z = Vector3::UnitZ();
  bool isotropic = true;
  double norm = 1.0;

  Matrix3 matrix() const {
    const double m11 = std::max(p[0], 1e-7), m22 = isotropic ? m11 : std::max(p[1], 1e-7);
    const double m13 = isotropic ? 0.0 : p[2];
    Matrix3 frame;
    frame.col(0) = Vector3(z.z(), 0.0, -z.x());
    frame.col(1) = Vector3::UnitY();
    frame.col(2) = z;
    Matrix3 shape;
    shape << m11, 0, m13, 0, m22, 0, 0, 0, 1;
    return frame * shape;
  }
};

double midpoint_error(const brdf::Lobe& lobe, const ltc::LtcDistribution& ltc) {
  double error = 0.0;
  const auto add = [&](const Vector3& l) {
    const auto target = lobe.evaluate(l);
    const double d = ltc.evaluate(l);
    const double pdf = target.pdf + d / ltc.amplitude();
    const double difference = std::abs(target.value - d);
    if (pdf > 0.0) error += difference * difference * difference / pdf;
  };
  for (int j = 0; j < samples; ++j)
    for (int i = 0; i < samples; ++i) {
      add(ltc.sample(midpoint(i), midpoint(j)));
      add(lobe.sample(midpoint(i), midpoint(j)));
    }
  return error / (samples * samples);
}

// Downhill simplex with the reference fitter's settings; returns the best point.
template <class F>
std::array<double, 3> nelder_mead(const std::array<double, 3>& start, const F& f) {
  constexpr double delta = 0.05, tolerance = 1e-5;
  constexpr int iterations = 100;
  std::array<std::array<double, 3>, 4> s;
  std::array<double, 4> v;
  for (int i = 0; i < 4; ++i) {
    s[i] = start;
    if (i > 0) s[i][i - 1] += delta;
    v[i] = f(s[i]);
  }
  for (int it = 0; it < iterations; ++it) {
    std::array<int, 4> order{0, 1, 2, 3};
    std::sort(order.begin(), order.end(), [&](int x, int y) { return v[x] < v[y]; });
    const int lo = order[0], nh = order[2], hi = order[3];
    if (2.0 * std::abs(v[hi] - v[lo]) / (std::abs(v[hi]) + std::abs(v[lo]) + 1e-30) < tolerance) break;
    std::array<double, 3> centre{};
    for (int i = 0; i < 4; ++i)
      if (i != hi)
        for (int k = 0; k < 3; ++k) centre[k] += s[i][k] / 3.0;
    const auto along = [&](double t) {
      std::array<double, 3> x;
      for (int k = 0; k < 3; ++k) x[k] = centre[k] + t * (s[hi][k] - centre[k]);
      return x;
    };
    const auto reflected = along(-1.0);
    const double fr = f(reflected);
    if (fr < v[lo]) {
      const auto expanded = along(-2.0);
      const double fe = f(expanded);
      if (fe < fr) s[hi] = expanded, v[hi] = fe;
      else s[hi] = reflected, v[hi] = fr;
    } else if (fr < v[nh]) {
      s[hi] = reflected, v[hi] = fr;
    } else {
      const auto contracted = along(0.5);
      const double fc = f(contracted);
      if (fc < v[hi]) {
        s[hi] = contracted, v[hi] = fc;
      } else {
        for (int i = 0; i < 4; ++i) {
          if (i == lo) continue;
          for (int k = 0; k < 3; ++k) s[i][k] = s[lo][k] + 0.5 * (s[i][k] - s[lo][k]);
          v[i] = f(s[i]);
        }
      }
    }
  }
  int best = 0;
  for (int i = 1; i < 4; ++i)
    if (v[i] < v[best]) best = i;
  return s[best];
}

double cos_theta(int t) {
  const double x = double(t) / (size - 1);
  return std::cos(std::min(std::acos(1.0 - x * x), 1.57));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: bench_ltc_reference FAMILY OURS.csv\n");
    return 2;
  }
  const auto family = brdf::find_family(argv[1]);
  if (!family) {
    std::fprintf(stderr, "bench_ltc_reference: no family '%s'\n", argv[1]);
    return 2;
  }
  std::vector<ltc::IsotropicParameters> ours(size * size);
  std::ifstream in(argv[2]);
  int t, a;
  double m00, m11, m02, m20;
  int read = 0;
  while (in >> t >> a >> m00 >> m11 >> m02 >> m20) ours[a + t * size] = {m00, m11, m02, m20}, ++read;
  if (read != size * size) {
    std::fprintf(stderr, "bench_ltc_reference: %s holds %d texels, not %d\n", argv[2], read, size * size);
    return 2;
  }

  // The procedure, timed.
  std::vector<Matrix3> theirs(size * size);
  const auto start = std::chrono::steady_clock::now();
  Fit fit;
  std::array<double, 3> first_of_previous_row{1.0, 1.0, 0.0};
  for (a = size - 1; a >= 0; --a)
    for (t = 0; t < size; ++t) {
      const auto lobe = brdf::make_family_lobe(*family, double(a) / (size - 1), cos_theta(t));
      const Moments moments = midpoint_moments(*lobe);
      fit.norm = moments.norm;
      if (t == 0) {
        fit.z = Vector3::UnitZ();
        fit.isotropic = true;
        fit.p = first_of_previous_row;
        fit.p[2] = 0.0;
      } else {
        fit.z = moments.direction;
        fit.isotropic = false;
      }
      fit.p = nelder_mead(fit.p, [&](const std::array<double, 3>& p) {
        Fit trial = fit;
        trial.p = p;
        const Matrix3 m = trial.matrix();
        if (!(std::abs(m.determinant()) > 1e-300)) return std::numeric_limits<double>::infinity();
        return midpoint_error(*lobe, ltc::LtcDistribution(m, std::max(fit.norm, 1e-300)));
      });
      if (fit.isotropic) fit.p[1] = fit.p[0], fit.p[2] = 0.0;
      theirs[a + t * size] = fit.matrix();
      if (t == 0) first_of_previous_row = {std::max(fit.p[0], 1e-7), std::max(fit.p[1], 1e-7), 0.0};
    }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Both tables judged alike.
  int cubed_wins = 0, l2_wins = 0;
  std::vector<double> ratios;
  for (t = 0; t < size; ++t)
    for (a = 0; a < size; ++a) {
      const ltc::IsotropicTarget target(brdf::make_family_lobe(*family, double(a) / (size - 1), cos_theta(t)),
                                        {16, 4096, 4096});
      const auto our = target.judge(target.matrix(ours[a + t * size]));
      const auto their = target.judge(theirs[a + t * size]);
      cubed_wins += our.cubed <= their.cubed;
      l2_wins += our.l2 <= their.l2;
      if (their.cubed > 0.0) ratios.push_back(our.cubed / their.cubed);
    }
  std::sort(ratios.begin(), ratios.end());
  std::printf("%s: reference procedure %.1f s on one core; pbrfit's table at or below it in %.2f %% of texels "
              "(cubed error), %.2f %% (L2); median ratio of cubed errors %.3f\n",
              argv[1], seconds, 100.0 * cubed_wins / (size * size), 100.0 * l2_wins / (size * size),
              ratios.empty() ? NAN : ratios[ratios.size() / 2]);
  return 0;
}
