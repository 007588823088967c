#pragma once
// The approximate models of a spherical light on GGX (Pesce & Iwanicki 2015, section 4.2), each a value for
// one view given its fit parameters, comparable with sphere_light.hpp's response (same normalization: a
// point light of unit irradiance at normal incidence). rho is ggx_lobe.hpp's cosine-weighted GGX.
//
//  - roughness modification (4.2.1): rho_{alpha'}(v, centre); parameter alpha'.
//  - capped roughness modification (4.2.2): softmin(rho_{alpha'}(v, centre), cap; s); parameters alpha', cap,
//    s < 0 (the course settles on s = -10).
//  - representative point (Karis 2013): scale * rho_{alpha'}(v, p), p the point of the sphere closest to the
//    reflected ray, with Karis' normalization (alpha / alpha'')^2, alpha'' = min(1, alpha + R / 3) as the
//    published scale and alpha' = alpha; parameters alpha', scale.
//  - smoothed representative point (4.2.3): as above with the clamp min(1, R / |c|) replaced by
//    softmin(1, R / |c|; s); the course ships s = -3, alpha' = alpha and the fitted normalization
//    1 / (a + b tan(gamma) / alpha^c), a = 0.962406, b = 0.375892, c = 0.962406 (values as printed).
// R = sin gamma is the radius of the light at distance 1; centre-to-ray c = (L.r) r - L with L the centre
// and r = reflect(-v, n).
#include "pbrfit/brdf/sphere_light.hpp"

namespace pbrfit::brdf {

// (x^s + y^s)^(1/s) for s < 0 and x, y >= 0 (-> min(x, y) as s -> -inf); 0 if either is 0.
double soft_minimum(double x, double y, double s);

double roughness_modification_model(double alpha_modified, const SphereLight& light, const Vector3& view);

double capped_roughness_model(double alpha_modified, double cap, double smoothness, const SphereLight& light,
                              const Vector3& view);

// The representative direction; smoothness == 0 selects Karis' hard clamp, s < 0 the soft minimum.
Vector3 representative_direction(const SphereLight& light, const Vector3& view, double smoothness);

double karis_sphere_normalization(double alpha, const SphereLight& light);

double representative_point_model(double alpha_modified, double scale, const SphereLight& light,
                                  const Vector3& view);

double smoothed_representative_point_model(double alpha_modified, double scale, double smoothness,
                                           const SphereLight& light, const Vector3& view);

double course_smoothed_normalization(double alpha, const SphereLight& light);

inline constexpr double course_capped_smoothness = -10.0;
inline constexpr double course_representative_smoothness = -3.0;

}  // namespace pbrfit::brdf
