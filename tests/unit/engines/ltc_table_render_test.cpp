// The check render of an LTC table (ltc/table_render.hpp): its scene, the texel a shader reads, the table's
// and the ground truth's shading of a pixel.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <vector>

#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/ltc/polygon_integral.hpp"
#include "pbrfit/ltc/table_render.hpp"

using namespace pbrfit::ltc;
using pbrfit::Vector3;

TEST_CASE("the check scene shows the plane from 35 to 70 degrees off the normal, dark behind the light", "[ltc]") {
  const PlaneScene scene = table_check_scene(32);
  std::size_t lit = 0, dark = 0;
  for (std::size_t row = 0; row < 32; ++row)
    for (std::size_t column = 0; column < 32; ++column) {
      const auto point = shading_point(scene, column, row);
      REQUIRE(point);  // every ray meets the plane
      const auto hit = scene.plane_hit(column + 0.5, row + 0.5);
      REQUIRE(hit);
      CHECK(point->lit == (hit->y() < 2.0));
      (point->lit ? lit : dark) += 1;
      CHECK(point->cos_theta_view > std::cos(71.0 * M_PI / 180.0));
      CHECK(point->cos_theta_view < std::cos(30.0 * M_PI / 180.0));
      // The light in the shading frame is the world's light seen from the point, turned about the normal.
      for (std::size_t i = 0; i < 4; ++i) {
        CHECK(std::abs(point->light.vertices[i].z() - scene.light[i].z()) < 1e-12);
        CHECK(std::abs(point->light.vertices[i].norm() - (scene.light[i] - *hit).norm()) < 1e-12);
      }
      // ... turned so that the view lies in the x-z plane, towards +x.
      const Vector3 to_camera = scene.camera - *hit;
      const Vector3 light_to_camera = to_camera - (scene.light[0] - *hit);
      const Vector3 local = point->light.vertices[0];
      const Vector3 view_local(std::sqrt(to_camera.x() * to_camera.x() + to_camera.y() * to_camera.y()), 0.0, to_camera.z());
      CHECK(std::abs((view_local - local).norm() - light_to_camera.norm()) < 1e-9);
    }
  CHECK(lit > 800);   // most of the image: the light's reflection fills it
  CHECK(dark > 0);    // the top rows look past the light
  const auto rows = render_plane(scene, 30, 2, [](const ShadingPoint&) { return 7.0; });
  REQUIRE(rows.size() == 64);
  CHECK(rows[5] == 7.0);
  CHECK_THROWS(render_plane(scene, 31, 2, [](const ShadingPoint&) { return 0.0; }));
}

TEST_CASE("a texel is read as linear filtering reads it, clamped at the ends", "[ltc]") {
  const std::vector<double> positions = {0.0, 0.5, 1.0};
  const std::vector<TableTexel> texels = {{{1, 0, 0, 1}, 1.0}, {{3, 2, -2, 5}, 0.5}, {{5, 4, -4, 9}, 0.25}};
  const TableTexel quarter = interpolated_texel(positions, texels, 0.25);
  CHECK(quarter.ltc_1 == ShaderForm{2, 1, -1, 3});
  CHECK(quarter.norm == 0.75);
  CHECK(interpolated_texel(positions, texels, 1.0).ltc_1 == texels[2].ltc_1);
  CHECK(interpolated_texel(positions, texels, -1.0).norm == 1.0);
  CHECK(interpolated_texel(positions, texels, 0.5).norm == 0.5);
  CHECK_THROWS(interpolated_texel(positions, std::vector<TableTexel>(2), 0.5));
}

TEST_CASE("the identity texel shades as the clamped cosine, scaled by its norm", "[ltc]") {
  const PlaneScene scene = table_check_scene(16);
  const auto point = shading_point(scene, 8, 12);
  REQUIRE(point);
  const double lambert = clamped_cosine_polygon_integral(point->light.vertices);
  CHECK(lambert > 0.01);
  CHECK(std::abs(table_shading({{1, 0, 0, 1}, 0.5}, point->light) - 0.5 * lambert) < 1e-15);
  CHECK(table_shading({{1, 0, 0, 1}, 0.0}, point->light) == 0.0);
  CHECK(std::isnan(table_shading({{NAN, 0, 0, 1}, 1.0}, point->light)));
}

// The row of the 64-pixel render where, from one tile per fan triangle, the cubature of a sharp GGX lobe
// settled 10 % low at two pixels: the ground truth agrees there with the integral to 1e-6.
TEST_CASE("the ground truth holds where a lobe's sharp peak lies near the light's edge", "[ltc]") {
  const PlaneScene scene = table_check_scene(64);
  const double r = 0.25396825396825395, alpha = r * r;
  QuadIntegralOptions tight = ground_truth_accuracy;
  tight.relative_tolerance = 1e-6;
  for (std::size_t column = 20; column < 44; ++column) {
    const auto point = shading_point(scene, column, 10);
    REQUIRE(point);
    const pbrfit::brdf::GgxLobe lobe(alpha, point->cos_theta_view);
    const double ours = lobe_shading(lobe, point->light);
    const double truth = lobe_quad_integral(lobe, point->light, *lobe.peak(), tight).value;
    INFO("column " << column);
    CHECK(std::abs(ours - truth) < 2.5e-3 * truth);
  }
}
