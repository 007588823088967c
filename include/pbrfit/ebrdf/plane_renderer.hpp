#pragma once
// The reference renderer of Nahmias 2022, chapter 4: a normal-mapped plane under a rectangular light
// (plane_scene.hpp), shaded by three methods, specular GGX plus Lambert diffuse:
//  - ground truth: every pixel supersampled on a stratified grid of S x S points, S = max(min_samples,
//    ceil(1.5 rho)) (at most 48) for rho texels per pixel, so that every texel of the footprint is seen;
//    each point shades its own MIP-0 micro-normal: the base GGX LTC at the micro-normal's view elevation
//    (ggx_ltc_curve.hpp) and the clamped cosine, integrated over the light polygon;
//  - naive: one normal per pixel from a mip-mapped normal map (box-filtered, trilinear, renormalized),
//    shaded like a MIP-0 point;
//  - ours: the prefiltered LTC tables (mip_tables.hpp: bilinear in views, trilinear in mips), the polygon
//    taken to the frame where the view azimuth is 0; below two texels per pixel MIP-0 shading of the
//    pixel centre's texel. TableFiltering::results shades each of the up to 8 mip texels a lookup blends
//    and blends what they shade (the radiance a pixel's footprint averages, as the ground truth does);
//    TableFiltering::matrices blends their matrices and shades once (what a cheap shader does).
// rho is the larger of the pixel's two texture-space steps (to the next column and row) in texels.
//
// Contract: images are resolution x resolution linear radiance (grey in all three channels), 0 where the
// ray misses the plane; a pure, deterministic function of its inputs.
#include <cstddef>
#include <optional>
#include <vector>

#include "pbrfit/core/rgb_image.hpp"
#include "pbrfit/ebrdf/ggx_ltc_curve.hpp"
#include "pbrfit/ebrdf/mip_tables.hpp"
#include "pbrfit/ebrdf/normal_map.hpp"
#include "pbrfit/ebrdf/plane_scene.hpp"

namespace pbrfit::ebrdf {

enum class RenderMethod { ground_truth, naive, ours };

enum class TableFiltering { results, matrices };

struct Shading {
  double light_radiance = 2.5;
  double specular = 0.3;  // colour (grey) of each component
  double diffuse = 0.6;
  std::size_t min_samples = 4;
  TableFiltering filtering = TableFiltering::results;
};

struct RenderInputs {
  const NormalMap* map = nullptr;
  const GgxLtcCurve* base_ltc = nullptr;
  const LtcMipTables* specular = nullptr;  // ours
  const LtcMipTables* diffuse = nullptr;   // ours
  Shading shading;
};

RgbImage render_plane(const PlaneScene& scene, RenderMethod method, const RenderInputs& inputs);

// Texels per pixel at the image centre.
double centre_texels_per_pixel(const PlaneScene& scene, std::size_t map_size);

const char* render_method_name(RenderMethod method);

}  // namespace pbrfit::ebrdf
