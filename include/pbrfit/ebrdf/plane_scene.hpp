#pragma once
// The scenes of Nahmias 2022, chapter 4: an infinite plane z = 0 carrying the normal map tiled once per
// world unit (texture coordinates u = x, v = y), lit by one rectangular area light, seen by a pinhole camera
// at a distance h. Everything scales with h, so the images look alike and only the texels per pixel change:
//  - top: the camera at height h looks straight down (+y up in the image); the light, a horizontal
//    rectangle of half-size 0.15 h at height 0.8 h offset by 0.1 h along x, shows its reflection;
//  - grazing: the camera at height 0.25 h looks at the plane's point h ahead (about 14 degrees above the
//    plane); the light, a vertical rectangle facing the camera, 0.3 h by 0.1 h, stands 0.8 h beyond.
// The light is not drawn and casts no shadow; it shines on both sides.
//
// The geometry (camera, rays, the plane) is ltc/plane_scene.hpp.
#include <cstddef>

#include "pbrfit/ltc/plane_scene.hpp"

namespace pbrfit::ebrdf {

enum class SceneView { top, grazing };

using ltc::PlaneScene;

PlaneScene make_plane_scene(SceneView view, double distance, std::size_t resolution);
const char* scene_view_name(SceneView view);

}  // namespace pbrfit::ebrdf
