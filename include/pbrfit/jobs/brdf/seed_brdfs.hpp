#pragma once
// The analytic BRDFs a search starts from, as expression texts of the inputs of brdf_inputs.hpp (brdf/direction_inputs.hpp) and the
// parameters p0..p3 (fitted per material and channel):
//  - cook_torrance, equation 5 of Brady et al. as printed: p0 = k_d, p1 = k_s, p2 = m, p3 = R0;
//    D = exp(-(tan(delta) / m)^2) / (m^2 cos^4 delta), delta = acos(n.h); G = min(1, 2 nh nv / vh, 2 nh nl / vh);
//    F = R0 + (1 - R0)(1 - n.h)^5; f = k_d + k_s F / pi D G / (nl nv);
//  - blinn_phong: k_d + k_s (n + 2) / (2 pi) nh^n with n = p2;
//  - ggx_smith: k_d / pi + k_s F D G1(l) G1(v) / (4 nl nv), GGX D and separable Smith G1 with alpha = p2,
//    Schlick F(v.h) with R0 = p3;
//  - brady_metal, brady_dielectric: the BRDFs the paper found (equations 6 and 7), p0 = k'_d, p1 = k'_s,
//    p2 = alpha, p3 = beta: k'_d / pi + k'_s D' G' F' with D' = exp(-delta / beta),
//    G' = min(alpha / k'_d v.h, 4 beta / (tan(delta) nv nl)), F' = alpha + (1 - v.h)^5; and
//    k'_d (1 + cos delta)^(1 - alpha) + min(1 / sqrt(k'_d), F(alpha, n.h) D(beta) / (pi vh nl nv))
//    exp(-tan(delta) / k'_s) / (alpha^2 (alpha + 2) beta), with F and D those of cook_torrance.
// A job's seed is the one edited; it and its codebank feed Insert edits; any of them can be evaluated
// beside the seed as a reference.
#include <string>
#include <vector>

namespace pbrfit::jobs::brdf {

struct SeedBrdf {
  std::string name;
  std::string expression;
};

const std::vector<SeedBrdf>& seed_brdfs();
const SeedBrdf* find_seed(const std::string& name);

}  // namespace pbrfit::jobs::brdf
