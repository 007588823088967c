#pragma once
// GGX (Trowbridge-Reitz) microfacet distribution and Smith masking-shadowing, isotropic.
// Angles are given as cosines with respect to the surface normal; alpha is the GGX width (alpha >= 0).

#include <array>

namespace pbrfit::brdf {

// D(h): normalized so that the integral of D(h) (n.h) over the hemisphere is 1 (alpha > 0); 0 for n.h < 0.
double ggx_distribution(double alpha, double n_dot_h);

// Smith Lambda for GGX: (-1 + sqrt(1 + alpha^2 tan^2)) / 2; 0 when alpha = 0, +inf at n.w <= 0 otherwise.
double ggx_smith_lambda(double alpha, double n_dot_w);

enum class SmithVisibility {
  separable,            // exact separable Smith GGX: G1(v) G1(l)
  separable_schlick,    // UE4 / Karis: Schlick-GGX G1 with k = alpha / 2, separable
  height_correlated,    // Heitz 2014 / Filament: 1 / (1 + Lambda(v) + Lambda(l))
};

inline constexpr std::array<SmithVisibility, 3> all_smith_visibilities = {
    SmithVisibility::separable, SmithVisibility::separable_schlick, SmithVisibility::height_correlated};

// G(v, l) for the given convention; 0 if n.v <= 0 or n.l <= 0, 1 in the mirror limit alpha = 0.
double smith_masking_shadowing(SmithVisibility visibility, double alpha, double n_dot_v, double n_dot_l);

// V = G / (4 (n.v) (n.l)), evaluated in forms that stay finite as n.v or n.l tends to 0 when alpha > 0
// (height_correlated still diverges when both do); 0 if n.v < 0 or n.l < 0.
double smith_visibility(SmithVisibility visibility, double alpha, double n_dot_v, double n_dot_l);

}  // namespace pbrfit::brdf
