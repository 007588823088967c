#pragma once
// Sweep problem `sphere_light` (Pesce & Iwanicki 2015, section 4): GGX lit by a uniform spherical light,
// over roughness r (alpha = r^2), the light's cone half-angle gamma and its incidence angle. A cell's target
// is the ground truth over the view hemisphere (brdf/sphere_light_target.hpp); the models are those of
// brdf/sphere_light_models.hpp. Error: the relative L^p distance over views, |truth - model|_p / |truth|_p.
// Anchors: the published forms at the same cell, Karis 2013 for the representative point (alpha' = alpha,
// his normalization) and the course's shipped smoothed representative point (alpha' = alpha, s = -3, its
// fitted normalization).
#include <memory>

#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/jobs/sweep/sweep_problem.hpp"

namespace pbrfit::jobs::sweep {

struct SphereLightSettings {
  double norm_p = 2.0;  // 1, 2, 3 or +inf
  int view_panels = 2;  // radial and azimuthal panels of 15 nodes each
  integrate::AdaptiveOptions truth;  // each view's cap integral
};

std::unique_ptr<SweepProblem> make_sphere_light_problem(const SphereLightSettings& settings);

}  // namespace pbrfit::jobs::sweep
