#include "pbrfit/jobs/ebrdf/ebrdf_workload.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "pbrfit/core/error.hpp"
#include "pbrfit/ebrdf/footprint_samples.hpp"

namespace pbrfit::jobs::ebrdf {
namespace {

namespace eb = pbrfit::ebrdf;

eb::EbrdfSampling sampling_for(const EbrdfSettings& s, const ComponentSettings& c, std::uint64_t seed) {
  return {{c.component, s.roughness * s.roughness}, c.views, s.samples, seed};
}

// The fit a view warm-starts from: the previous azimuth, or for azimuth 0 the previous elevation's.
std::optional<std::size_t> warm_view(std::size_t view, std::size_t n_phi) {
  if (view % n_phi != 0) return view - 1;
  if (view >= n_phi) return view - n_phi;
  return std::nullopt;
}

}  // namespace

std::string level_group(const ComponentSettings& component, std::size_t level) {
  return std::string("ebrdf/") + component_name(component.component) + "/mip" + std::to_string(level);
}

EbrdfWorkload::EbrdfWorkload(EbrdfSettings settings) : settings_(std::move(settings)), items_(settings_) {
  for (const auto& c : settings_.components) base_lobes_.emplace_back(eb::BaseLobe{c.component, settings_.roughness * settings_.roughness});
  add_stage(runtime::stage<Nothing, Nothing, TileFits>("tiles", 1, this)
                .items(&EbrdfWorkload::item_total)
                .compute(&EbrdfWorkload::compute_item)
                .check(&EbrdfWorkload::check_item)
                .blocks(&EbrdfWorkload::item_blocks)
                .fold(&EbrdfWorkload::fold_item));
}

std::size_t EbrdfWorkload::fits_in(const TileItem& tile) const {
  return tile.width * tile.height * settings_.components[tile.component].views.count();
}

EbrdfWorkload::TileFits EbrdfWorkload::fit_tile(const TileItem& tile, const Task& task) const {
  const ComponentSettings& component = settings_.components[tile.component];
  const eb::FootprintSampler sampler(*settings_.map, sampling_for(settings_, component, task.seed()),
                                     base_lobes_[tile.component]);
  const std::size_t views = component.views.count();
  std::vector<float> out;
  out.reserve(fits_in(tile) * values_per_fit);
  for (std::size_t y = tile.y0; y < tile.y0 + tile.height; ++y)
    for (std::size_t x = tile.x0; x < tile.x0 + tile.width; ++x) {
      if (task.stop_requested()) throw runtime::Cancelled();
      const eb::MipTexel texel{tile.level, x, y};
      const auto contributing = sampler.contributing_texels(texel);
      std::vector<Matrix3> fitted(views);
      for (std::size_t v = 0; v < views; ++v) {
        const auto samples = sampler.samples(contributing, v);
        RandomStream sgd_random = task.random((y * tile.side + x) * views + v);
        const auto warm = warm_view(v, component.views.n_phi);
        const eb::EbrdfFit fit = eb::fit_ebrdf(samples, sampler.amplitude(texel, v), settings_.fit, sgd_random,
                                               warm ? &fitted[*warm] : nullptr);
        fitted[v] = eb::fit_matrix(fit);
        for (double m : fit.matrix) out.push_back(float(m));
        out.push_back(float(fit.amplitude));
        out.push_back(float(fit.error));
      }
    }
  return out;
}

EbrdfWorkload::TileFits EbrdfWorkload::compute_item(const Task& task) const {
  if (task.item() == 0) return {};  // the normal map: its blocks come from the map itself
  return fit_tile(items_.find(task.item()), task);
}

void EbrdfWorkload::check_item(const runtime::StageItem& at, const TileFits& fits) const {
  const std::size_t expected = at.item() == 0 ? 0 : fits_in(items_.find(at.item())) * values_per_fit;
  if (fits.size() != expected) throw RunError("ebrdf: a tile result has the wrong length");
}

std::vector<store::Block> EbrdfWorkload::item_blocks(const runtime::StageItem& at, const TileFits& values) const {
  const WorkItemId id = at.id;
  if (id.item == 0) {
    const std::uint64_t n = settings_.map->size();
    store::Block normals{"ebrdf/normal_map", "normal", {0, 0, 0}, {n, n, 3}};
    for (const auto& v : settings_.map->normals()) normals.values.insert(normals.values.end(), {v.x(), v.y(), v.z()});
    return {normals};
  }
  const TileItem& tile = items_.find(id.item);
  const ComponentSettings& component = settings_.components[tile.component];
  const std::uint64_t nt = component.views.n_theta, np = component.views.n_phi;
  const std::string group = level_group(component, tile.level);
  const std::vector<std::uint64_t> offset = {tile.y0, tile.x0, 0, 0};
  const std::vector<std::uint64_t> count = {tile.height, tile.width, nt, np};
  store::Block matrix{group, "matrix", {tile.y0, tile.x0, 0, 0, 0}, {tile.height, tile.width, nt, np, 9}};
  store::Block amplitude{group, "amplitude", offset, count};
  store::Block error{group, "error", offset, count};
  for (std::size_t f = 0; f < values.size() / values_per_fit; ++f) {
    const float* fit = values.data() + f * values_per_fit;
    matrix.values.insert(matrix.values.end(), fit, fit + 9);
    amplitude.values.push_back(fit[9]);
    error.values.push_back(fit[10]);
  }
  return {std::move(matrix), std::move(amplitude), std::move(error)};
}

void EbrdfWorkload::fold_item(Summary& sum, const runtime::StageItem&, const TileFits& values) const {
  for (std::size_t f = 0; f < values.size() / values_per_fit; ++f) {
    const double error = values[f * values_per_fit + 10];
    ++sum.fits;
    sum.error_sum_micro += std::uint64_t(std::llround(std::max(0.0, error) * 1e6));
    sum.max_error = std::max(sum.max_error, error);
  }
}

std::string EbrdfWorkload::headline_of(const Summary& sum) const {
  if (sum.fits == 0) return "no fits yet";
  char text[160];
  std::snprintf(text, sizeof text, "%llu LTC fits, mean sliced Wasserstein error %.4f, max %.4f",
                static_cast<unsigned long long>(sum.fits), double(sum.error_sum_micro) * 1e-6 / double(sum.fits),
                sum.max_error);
  return text;
}

}  // namespace pbrfit::jobs::ebrdf
