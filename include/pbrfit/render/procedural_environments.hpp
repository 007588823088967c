#pragma once
// Two lighting environments made from formulas, so that renders need no downloaded map. Each texel holds
// the radiance in the direction of its centre (no filtering); both are 256 x 128 and deterministic.
//
// procedural_interior(): a room lit by three daylight windows (radiance about 20 to 26, at elevations
// 5 to 35 degrees, azimuths 35, 160 and 260 degrees from +z) and a round ceiling light around +y
// (12 degrees across the radius, about 40); walls dim (about 0.5, some 50 times darker), the ceiling a
// little brighter, the floor (below the horizon) warm brown.
// procedural_sky(): a clear sky graded from a pale horizon (about 1.3) to a blue zenith, a bright halo
// around a sun of 2.5 degrees radius (radiance about 3000) at elevation 35 and azimuth 40 degrees, and a
// dim ground.
#include "pbrfit/render/environment_map.hpp"

namespace pbrfit::render {

EnvironmentMap procedural_interior();
EnvironmentMap procedural_sky();

}  // namespace pbrfit::render
