#pragma once
// The check render of an isotropic LTC table, the picture a rendering engineer looks at before shipping one
// (Heitz et al. 2016 judge their tables by such renders): a plane under a rectangular light, shaded per pixel
// by the table as a shader reads it and by the lobe's own integral over the light (the ground truth).
//
// The scene (table_check_scene): the plane z = 0 seen by a camera at (0, -2, 1.6) looking at (0, 0.07, 0)
// with a vertical field of view of 2 atan(0.311) (about 35 degrees), so views run from about 35 degrees off
// the normal at the bottom of the image to 70 at the top; a rectangle light 2 wide, standing upright on the
// line y = 2 from z = 0.2 to 1.2, facing the camera (one-sided: the few points beyond y = 2, in the top
// rows, see its back and are dark). Radiance 1, F = 1: a pixel's value is the integral of the
// cosine-weighted lobe over the light.
//
// shading_point gives what a table and a lobe are evaluated with at a pixel centre: cos theta_v and the
// light's vertices in the shading frame of brdf/lobe.hpp (n = +z, the view in the x-z plane with x >= 0).
// render_plane fills rows [first_row, first_row + rows) of a resolution x resolution image (row 0 at the top),
// row-major: NaN where the ray misses the plane, 0 where the point sees the light's back, shade(point)
// elsewhere.
//
// A texel of the table is what the shaders store (shader_form.hpp): ltc_1 and the norm (ltc_2's first
// component). interpolated_texel is the texel a shader reads with linear filtering at view value x between
// texels at increasing positions, clamped to the ends (as a clamped texture is).
//
// Invariants: pure, deterministic functions of their arguments.
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "pbrfit/ltc/plane_scene.hpp"
#include "pbrfit/ltc/polygon_lighting.hpp"
#include "pbrfit/ltc/shader_form.hpp"

namespace pbrfit::ltc {

PlaneScene table_check_scene(std::size_t resolution);

struct ShadingPoint {
  double cos_theta_view = 1.0;
  Quad light;         // in the shading frame
  bool lit = true;    // false where the point sees the light's back
};

std::optional<ShadingPoint> shading_point(const PlaneScene& scene, std::size_t column, std::size_t row);

std::vector<double> render_plane(const PlaneScene& scene, std::size_t first_row, std::size_t rows,
                                 const std::function<double(const ShadingPoint&)>& shade);

struct TableTexel {
  ShaderForm ltc_1 = {1.0, 0.0, 0.0, 1.0};
  double norm = 0.0;
};

TableTexel interpolated_texel(std::span<const double> positions, std::span<const TableTexel> texels, double x);

// The table's shading of a point: norm x the LTC's integral over the light (0 for a texel with no LTC, NaN for
// one with a NaN, as the published table has off its grid).
double table_shading(const TableTexel& texel, const Quad& light);

// The texel's LTC at a direction: norm x D(l) (0 for a texel with no LTC, NaN for one with a NaN).
double table_value(const TableTexel& texel, const Vector3& l);

// The ground truth's: the lobe's integral over the light (lobe_quad_integral about the lobe's peak, or the
// mirror direction), NaN where the cubature does not converge. Started from one tile per fan triangle, the
// cubature now and then settles on a value 10 % low in a pixel whose light holds a sharp peak near an edge;
// from 4 x 4 tiles at a relative tolerance of 1e-3 every pixel of the GGX table's render is within 0.25 % of
// the integral to 1e-5, at a fifth of its cost.
inline constexpr QuadIntegralOptions ground_truth_accuracy{1e-3, 1e-10, 2'000'000, 4};

double lobe_shading(const brdf::Lobe& lobe, const Quad& light);

}  // namespace pbrfit::ltc
