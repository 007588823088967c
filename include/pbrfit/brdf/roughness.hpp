#pragma once
// Roughness parametrizations: how a table's roughness axis value maps to the GGX alpha.

namespace pbrfit::brdf {

enum class RoughnessParametrization {
  perceptual,  // alpha = r^2 (Burley / UE4 / Filament perceptual roughness)
  linear,      // alpha = r
  gloss,       // alpha = (1 - g)^4 (Narkowicz 2014 gloss remap)
};

double alpha_from(RoughnessParametrization parametrization, double axis_value);

// A short formula for documentation and result attributes, e.g. "alpha = r^2".
const char* formula(RoughnessParametrization parametrization);

}  // namespace pbrfit::brdf
