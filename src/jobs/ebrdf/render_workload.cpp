#include "pbrfit/jobs/ebrdf/render_workload.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pbrfit/core/error.hpp"
#include "pbrfit/render/image_metrics.hpp"

namespace pbrfit::jobs::ebrdf {
namespace {

namespace eb = pbrfit::ebrdf;

constexpr eb::RenderMethod methods[] = {eb::RenderMethod::ground_truth, eb::RenderMethod::naive,
                                        eb::RenderMethod::ours};

double display(float linear, double exposure) {
  return std::pow(std::clamp(double(linear) * exposure, 0.0, 1.0), 1.0 / 2.2);
}

// MSE of the display values over the pixels that see the plane.
double display_mse(const RgbImage& image, const RgbImage& truth, const eb::PlaneScene& scene, double exposure) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t row = 0; row < scene.resolution; ++row)
    for (std::size_t column = 0; column < scene.resolution; ++column) {
      if (!scene.plane_hit(double(column) + 0.5, double(row) + 0.5)) continue;
      const double d = display(image.pixel(column, row)[0], exposure) - display(truth.pixel(column, row)[0], exposure);
      sum += d * d;
      ++count;
    }
  return count ? sum / double(count) : 0.0;
}

// The pixels that see the plane (1) and those that do not (0).
std::vector<std::uint8_t> plane_mask(const eb::PlaneScene& scene) {
  std::vector<std::uint8_t> mask(scene.resolution * scene.resolution, 0);
  for (std::size_t row = 0; row < scene.resolution; ++row)
    for (std::size_t column = 0; column < scene.resolution; ++column)
      mask[row * scene.resolution + column] = scene.plane_hit(double(column) + 0.5, double(row) + 0.5) ? 1 : 0;
  return mask;
}

// The highlight: the plane's pixels where the ground truth has at least a quarter of its brightest radiance.
std::vector<std::uint8_t> highlight_mask(const RgbImage& truth, const std::vector<std::uint8_t>& plane) {
  float brightest = 0.0f;
  for (std::size_t p = 0; p < plane.size(); ++p)
    if (plane[p]) brightest = std::max(brightest, truth.values()[3 * p]);
  std::vector<std::uint8_t> mask(plane.size(), 0);
  for (std::size_t p = 0; p < plane.size(); ++p) mask[p] = plane[p] && truth.values()[3 * p] >= 0.25f * brightest;
  return mask;
}

// The mean linear radiance over the marked pixels (0 when none is marked).
double mean_radiance(const RgbImage& image, const std::vector<std::uint8_t>& mask) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t p = 0; p < mask.size(); ++p)
    if (mask[p]) sum += image.values()[3 * p], ++count;
  return count ? sum / double(count) : 0.0;
}

RgbImage display_image(const RgbImage& linear, double exposure) {
  RgbImage shown(linear.width(), linear.height());
  for (std::size_t row = 0; row < linear.height(); ++row)
    for (std::size_t column = 0; column < linear.width(); ++column) {
      const auto v = float(display(linear.pixel(column, row)[0], exposure));
      shown.set(column, row, {v, v, v});
    }
  return shown;
}

}  // namespace

RenderWorkload::RenderWorkload(RenderSettings settings)
    : settings_(std::move(settings)), base_ltc_(settings_.tables->alpha) {
  add_stage(runtime::stage<Nothing, Nothing, Rendered>("views", 1, this)
                .items(&RenderWorkload::view_count)
                .compute(&RenderWorkload::render)
                .check(&RenderWorkload::check_render)
                .blocks(&RenderWorkload::render_blocks)
                .fold(&RenderWorkload::fold_render));
}

RenderWorkload::Rendered RenderWorkload::render(const runtime::StageTask<Nothing, Nothing>& task) const {
  const std::size_t scene_index = task.item() / settings_.distances.size();
  const double distance = settings_.distances[task.item() % settings_.distances.size()];
  const eb::PlaneScene scene = eb::make_plane_scene(settings_.scenes[scene_index], distance, settings_.resolution);
  const PrefilteredTables& t = *settings_.tables;
  const eb::RenderInputs inputs{t.map.get(), &base_ltc_, &*t.specular, &*t.diffuse, settings_.shading};
  std::vector<RgbImage> images;
  for (const auto method : methods) {
    if (task.stop_requested()) throw runtime::Cancelled();
    images.push_back(eb::render_plane(scene, method, inputs));
  }
  Rendered r;
  for (const RgbImage& image : images)
    for (float v : image.values()) r.display.push_back(std::uint8_t(std::lround(255.0 * display(v, settings_.exposure))));
  r.naive_mse = display_mse(images[1], images[0], scene, settings_.exposure);
  r.ours_mse = display_mse(images[2], images[0], scene, settings_.exposure);
  r.texels_per_pixel = eb::centre_texels_per_pixel(scene, t.map->size());
  const auto plane = plane_mask(scene);
  if (std::find(plane.begin(), plane.end(), 1) == plane.end()) return r;  // no pixel sees the plane
  const auto highlight = highlight_mask(images[0], plane);
  for (const RgbImage& image : images) {
    r.energy.push_back(mean_radiance(image, plane));
    r.highlight_energy.push_back(mean_radiance(image, highlight));
  }
  const RgbImage truth = display_image(images[0], settings_.exposure);
  r.naive_ssim = render::ssim(truth, display_image(images[1], settings_.exposure), plane);
  r.ours_ssim = render::ssim(truth, display_image(images[2], settings_.exposure), plane);
  return r;
}

void RenderWorkload::check_render(const runtime::StageItem&, const Rendered& r) const {
  if (r.display.size() != 3 * settings_.resolution * settings_.resolution * 3)
    throw RunError("ebrdf_render: a rendered item has the wrong size");
}

std::vector<store::Block> RenderWorkload::render_blocks(const runtime::StageItem& at, const Rendered& r) const {
  const WorkItemId id = at.id;
  const std::uint64_t scene = id.item / settings_.distances.size(), distance = id.item % settings_.distances.size();
  const std::uint64_t n = settings_.resolution;
  store::Block renders{"ebrdf_render", "renders", {scene, distance, 0, 0, 0, 0}, {1, 1, 3, n, n, 3}};
  renders.values.assign(r.display.begin(), r.display.end());
  const auto per_method = [](const std::vector<double>& values) {  // empty when no pixel sees the plane
    std::vector<store::Number> out(values.begin(), values.end());
    out.resize(3, 0.0);
    return out;
  };
  return {std::move(renders),
          {"ebrdf_render", "mse", {scene, distance, 0}, {1, 1, 2}, {r.naive_mse, r.ours_mse}},
          {"ebrdf_render", "ssim", {scene, distance, 0}, {1, 1, 2}, {r.naive_ssim, r.ours_ssim}},
          {"ebrdf_render", "energy", {scene, distance, 0}, {1, 1, 3}, per_method(r.energy)},
          {"ebrdf_render", "highlight_energy", {scene, distance, 0}, {1, 1, 3}, per_method(r.highlight_energy)},
          {"ebrdf_render", "texels_per_pixel", {scene, distance}, {1, 1}, {r.texels_per_pixel}}};
}

void RenderWorkload::fold_render(Summary& sum, const runtime::StageItem&, const Rendered& r) const {
  ++sum.images;
  if (r.texels_per_pixel >= 2.0) {
    ++sum.compared;
    sum.ours_better += r.ours_mse < r.naive_mse;
  }
  if (r.energy.size() == 3 && std::abs(r.energy[2] - r.energy[0]) <= 0.05 * r.energy[0]) ++sum.energy_held;
}

std::string RenderWorkload::headline_of(const Summary& sum) const {
  char text[240];
  std::snprintf(text, sizeof text,
                "%llu scene views rendered; prefiltered below naive in %llu of %llu with >= 2 texels per pixel; "
                "within 5 %% of the ground truth's energy in %llu of %llu",
                static_cast<unsigned long long>(sum.images), static_cast<unsigned long long>(sum.ours_better),
                static_cast<unsigned long long>(sum.compared), static_cast<unsigned long long>(sum.energy_held),
                static_cast<unsigned long long>(sum.images));
  return text;
}

store::ResultLayout RenderWorkload::layout() const {
  store::Group g;
  g.name = "ebrdf_render";
  g.description = "a normal-mapped plane under a rectangular light (Nahmias 2022, chapter 4): ground truth "
                  "(supersampled MIP-0 texels), naive (mip-mapped normals) and ours (prefiltered LTCs)";
  char shading[260];
  std::snprintf(shading, sizeof shading,
                "light radiance %g; specular %g (GGX alpha %g) + diffuse %g (Lambert); exposure %g; ours blends the %s",
                settings_.shading.light_radiance, settings_.shading.specular, settings_.tables->alpha,
                settings_.shading.diffuse, settings_.exposure,
                settings_.shading.filtering == eb::TableFiltering::results ? "mip texels' results" : "mip texels' matrices");
  std::vector<double> scenes(settings_.scenes.size());
  std::string scene_names;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    scenes[i] = double(i);
    scene_names += (i ? ", " : "") + std::string(eb::scene_view_name(settings_.scenes[i]));
  }
  g.attributes = {{"tables", settings_.tables_path}, {"scenes", scene_names}, {"shading", shading},
                  {"methods", "ground_truth, naive, ours"},
                  {"mse", "mean squared difference of the sRGB display values in [0, 1] from the ground truth, over the "
                          "pixels that see the plane"},
                  {"ssim", "mean SSIM of the display values against the ground truth (11 x 11 Gaussian window, sigma 1.5), "
                           "over the pixels that see the plane"},
                  {"energy", "mean linear radiance over the pixels that see the plane"},
                  {"highlight_energy", "mean linear radiance over the highlight: the pixels where the ground truth has at "
                                       "least a quarter of its brightest pixel's radiance"}};
  const std::size_t n = settings_.resolution;
  std::vector<double> rows(n), methods_axis = {0, 1, 2}, compared = {0, 1}, channels = {0, 1, 2};
  for (std::size_t i = 0; i < n; ++i) rows[i] = double(i);
  g.axes = {{"scene", scenes, "scene index: " + scene_names},
            {"distance", settings_.distances, "camera distance h (the map tiles once per world unit)"},
            {"method", methods_axis, "0 ground_truth, 1 naive, 2 ours"},
            {"compared", compared, "0 naive, 1 ours"},
            {"row", rows, "pixel row, 0 at the top"},
            {"column", rows, "pixel column"},
            {"channel", channels, "R, G, B"}};
  store::Table renders{"renders", {"scene", "distance", "method", "row", "column", "channel"},
                       "sRGB display renders of each method", store::ValueType::u8};
  renders.chunk = {1, 1, 3, n, n, 3};
  g.tables = {renders,
              {"mse", {"scene", "distance", "compared"}, "MSE against the ground truth: naive, ours"},
              {"ssim", {"scene", "distance", "compared"}, "SSIM against the ground truth: naive, ours"},
              {"energy", {"scene", "distance", "method"}, "mean linear radiance of the plane: ground truth, naive, ours"},
              {"highlight_energy", {"scene", "distance", "method"},
               "mean linear radiance of the highlight: ground truth, naive, ours"},
              {"texels_per_pixel", {"scene", "distance"}, "texels per pixel at the image centre"}};
  return {{g}};
}

}  // namespace pbrfit::jobs::ebrdf
