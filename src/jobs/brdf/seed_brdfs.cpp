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
  };
  return seeds;
}

const SeedBrdf* find_seed(const std::string& name) {
  for (const auto& seed : seed_brdfs())
    if (seed.name == name) return &seed;
  return nullptr;
}

}  // namespace pbrfit::jobs::brdf
