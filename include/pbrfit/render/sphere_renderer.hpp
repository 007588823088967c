#pragma once
// Renders of the sphere from its stored light samples (sphere_samples.hpp): pixel value = sum over the
// pixel's samples of f(wi, wo) x weight, per channel, with f given as a callable on local directions
// (normal +z, wo towards the camera) or as a tabulated MERL BRDF read at each sample's stored cell.
//
// Invariants: images are resolution x resolution, black off the sphere (SphereView::mask); a render of a
// pixel range writes those pixels only, so callers may render disjoint ranges on separate threads into
// one image (the engine starts no threads); results do not depend on how the pixels are split.
// Missing (NaN) cells of a MERL table contribute nothing.
#include "pbrfit/brdf/merl_table.hpp"
#include "pbrfit/core/rgb_image.hpp"
#include "pbrfit/render/brdf_function.hpp"
#include "pbrfit/render/sphere_samples.hpp"

namespace pbrfit::render {

// A black image of the samples' resolution, ready for the range renders.
RgbImage blank_render(const SphereSamples& samples);

void render_pixels(const SphereSamples& samples, const BrdfFunction& brdf, PixelRange range, RgbImage& image);
void render_pixels(const SphereSamples& samples, const brdf::MerlTable& table, PixelRange range, RgbImage& image);

RgbImage render_sphere(const SphereSamples& samples, const BrdfFunction& brdf);
RgbImage render_sphere(const SphereSamples& samples, const brdf::MerlTable& table);

}  // namespace pbrfit::render
