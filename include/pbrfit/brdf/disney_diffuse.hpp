#pragma once
// The Disney diffuse BRDF (Burley 2012) with baseColor = 1, weighted by the cosine of the light (the
// "CBRDF" of Pesce & Iwanicki 2015, section 6):
//   rho(l) = (1/pi) (1 + (F_D90 - 1)(1 - n.l)^5) (1 + (F_D90 - 1)(1 - n.v)^5) (n.l),
//   F_D90 = 0.5 + 2 roughness (l.h)^2,  h = normalize(v + l),
// in the shading frame (n = +z), for unit v and l; 0 when n.l <= 0 or n.v < 0.
// Limits: roughness only enters through F_D90; at F_D90 = 1 the lobe is Lambert's (n.l)/pi.
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::brdf {

double disney_diffuse_cbrdf(double roughness, const Vector3& v, const Vector3& l);

// The Schlick-like retro-reflection factor 1 + (F_D90 - 1)(1 - cos)^5 of one direction.
double disney_retro_factor(double f_d90, double cosine);

}  // namespace pbrfit::brdf
