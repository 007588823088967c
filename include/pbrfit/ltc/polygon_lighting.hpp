#pragma once
// How well an LTC table lights polygons, the use it is made for: for a set of quad lights around the shading
// point, the LTC's polygon integral times its norm against the lobe's own integral over each quad, as a
// relative error (Heitz et al. 2016 judge their tables by renders of such lights).
//
// The quads (random_quads) are a fixed, seeded set shared by every cell and table, so tables compare on the
// same lights. Quad k: an angular size s log-uniform in [1, 90] degrees (the angle its side subtends at
// distance 1 before tilting), a centre direction uniform in solid angle over the upper hemisphere (so quads
// near the horizon cross it), a square of half-side tan(s / 2) at distance 1 turned by a uniform angle about
// that direction and tilted by up to 60 degrees about a random axis across it. Vertices are relative to the
// shading point; the plane of a quad never contains it.
//
// The lobe's integral (lobe_quad_integral) is over the part of the quad above the horizon (rho is 0 below):
// the clipped planar polygon is cut into triangles fanned from the point nearest the lobe's peak direction
// (where the ray of the peak meets the plane, or the closest point of the polygon to it), and each triangle
// (apex a, edge b -> c) is integrated over (s, tau) in [0, 1]^2 at x = a + tau^4 ((b + s (c - b)) - a), so a
// sharp peak at the apex spreads over many nodes: the integrand is rho(x / |x|) |n . x| / |x|^3 times the
// area Jacobian, by globally adaptive cubature (integrate/adaptive_cubature.hpp) to a relative tolerance.
// The LTC's integral (ltc_quad_integral) is what a shader computes: the norm times the clamped cosine over
// M^-1 of the whole quad (its part below the surface's horizon included, as the shader sees it).
//
// Invariants: everything here is a pure, deterministic function of its arguments.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pbrfit/brdf/lobe.hpp"
#include "pbrfit/geometry/vector.hpp"
#include "pbrfit/ltc/distribution.hpp"

namespace pbrfit::ltc {

struct Quad {
  std::array<Vector3, 4> vertices;
};

// The seed of the quads every table is judged with, and of those a table fitted to lights is fitted to
// (docs/results-sweep.md): two sets, so no table is judged by the lights it was fitted to.
inline constexpr std::uint64_t polygon_quad_seed = 20161;
inline constexpr std::uint64_t training_quad_seed = 20162;

std::vector<Quad> random_quads(std::size_t count, std::uint64_t seed = polygon_quad_seed);

struct QuadIntegralOptions {
  double relative_tolerance = 1e-3;
  double absolute_tolerance = 1e-9;
  std::size_t max_evaluations = 400'000;  // per quad
  // The cubature starts from this many tiles a side per fan triangle: more find narrow features (a sharp
  // peak near an edge) that a single tile's error estimate can miss.
  std::size_t initial_tiles_per_side = 1;
};

struct QuadIntegral {
  double value = 0.0;
  double error_estimate = 0.0;
  double solid_angle = 0.0;  // of the quad's part above the horizon
  std::size_t evaluations = 0;
  bool converged = true;
};

QuadIntegral lobe_quad_integral(const brdf::Lobe& lobe, const Quad& quad, const Vector3& peak,
                                const QuadIntegralOptions& options = {});

double ltc_quad_integral(const LtcDistribution& ltc, const Quad& quad);

// The largest value of rho over the peak direction and an equal-area 32 x 64 grid of the upper hemisphere.
double lobe_peak_value(const brdf::Lobe& lobe, const Vector3& peak);

// How far the approximations are from the lobe's own integrals over the quads:
//  - median and p95: of the relative errors |approximation - reference| / reference over the lights inside the
//    lobe, those where the lobe's mean value (reference / solid angle) is at least in_lobe_share of its peak
//    value; in the far tail an LTC is exactly 0 (its support ends at a great circle) and a relative error
//    there says nothing a viewer sees. Linear interpolation between order statistics; NaN when none counts.
//  - weighted: sum of |approximation - reference| over all lights / sum of reference, free of any threshold.
struct PolygonErrors {
  double median = 0.0;
  double p95 = 0.0;
  double weighted = 0.0;
  std::size_t counted = 0;
};

inline constexpr double in_lobe_share = 0.01;

PolygonErrors polygon_errors(std::span<const QuadIntegral> reference, std::span<const double> approximation,
                             double peak_value, double share = in_lobe_share);

// A set of quad lights with the lobe's own integrals over them, made once: judges LTCs by errors(), and is a
// fitting objective by score(): the root mean square of the relative errors over the lights inside the lobe
// plus the weighted error over all of them (both 0 for a perfect LTC; smooth where the LTC varies smoothly).
class PolygonLights {
 public:
  PolygonLights(const brdf::Lobe& lobe, std::vector<Quad> quads, const Vector3& peak,
                const QuadIntegralOptions& options = {});

  const std::vector<QuadIntegral>& reference() const { return reference_; }
  double peak_value() const { return peak_value_; }
  std::vector<double> integrals(const LtcDistribution& ltc) const;
  PolygonErrors errors(const LtcDistribution& ltc) const;
  double score(const LtcDistribution& ltc) const;

 private:
  std::vector<Quad> quads_;
  std::vector<QuadIntegral> reference_;
  double peak_value_ = 0.0;
};

}  // namespace pbrfit::ltc
