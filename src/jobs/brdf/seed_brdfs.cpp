#include "pbrfit/jobs/brdf/seed_brdfs.hpp"

namespace pbrfit::jobs::brdf {

const std::vector<SeedBrdf>& seed_brdfs() {
  static const std::vector<SeedBrdf> seeds = {
      {"cook_torrance",
       "t = tan(acos(nh)) / p2\n"
       "d = exp(-(t * t)) / (p2 * p2 * (nh * nh) * (nh * nh))\n"
       "g = min(1, min(2 * nh * nv / vh, 2 * nh * nl / vh))\n"
       "f = p3 + (1 - p3) * pow(1 - nh, 5)\n"
       "p0 + p1 * f / 3.141592653589793 * d * g / (nl * nv)"},
      {"blinn_phong", "p0 + p1 * (p2 + 2) / (2 * 3.141592653589793) * pow(nh, p2)"},
      {"ggx_smith",
       "a = p2 * p2\n"
       "q = nh * nh * (a - 1) + 1\n"
       "d = a / (3.141592653589793 * q * q)\n"
       "gl = 2 * nl / (nl + sqrt(a + (1 - a) * nl * nl))\n"
       "gv = 2 * nv / (nv + sqrt(a + (1 - a) * nv * nv))\n"
       "f = p3 + (1 - p3) * pow(1 - vh, 5)\n"
       "p0 / 3.141592653589793 + p1 * f * d * gl * gv / (4 * nl * nv)"},
      {"brady_metal",
       "delta = acos(nh)\n"
       "d = exp(-delta / p3)\n"
       "g = min(p2 / p0 * vh, 4 * p3 / (tan(delta) * nv * nl))\n"
       "f = p2 + pow(1 - vh, 5)\n"
       "p0 / 3.141592653589793 + p1 * d * g * f"},
      {"brady_dielectric",
       "t = tan(acos(nh))\n"
       "rd = pow(1 + nh, 1 - p2)\n"
       "f = p2 + (1 - p2) * pow(1 - nh, 5)\n"
       "d = exp(-(t / p3) * (t / p3)) / (p3 * p3 * (nh * nh) * (nh * nh))\n"
       "s1 = min(1 / sqrt(p0), f * d / (3.141592653589793 * vh * nl * nv))\n"
       "s2 = exp(-t / p1) / (p2 * p2 * (p2 + 2) * p3)\n"
       "p0 * rd + s1 * s2"},
  };
  return seeds;
}

const SeedBrdf* find_seed(const std::string& name) {
  for (const auto& seed : seed_brdfs())
    if (seed.name == name) return &seed;
  return nullptr;
}

}  // namespace pbrfit::jobs::brdf
