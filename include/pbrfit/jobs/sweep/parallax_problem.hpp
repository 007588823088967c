#pragma once
// Sweep problems `parallax_distance` and `parallax_angle` (Pesce & Iwanicki 2015, section 8): the
// perpendicular lobe at distance 1 (and, for the angle study, shifted along the line to the ray origin's
// foot) that best matches a GGX lobe projected on a plane (brdf/parallax_fit_error.hpp), over roughness r
// (alpha = r^2) and the source's distance or incidence angle. Error: the relative L2 distance over the
// window, sqrt(integral (P_source - scale P_candidate - offset)^2 / integral P_source^2), each integral
// adaptive at the tolerance the optimizer asks for (cooperative accuracy, from coarse_tolerance down to
// tolerance).
#include <memory>

#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/jobs/sweep/sweep_problem.hpp"

namespace pbrfit::jobs::sweep {

enum class ParallaxStudy { distance, angle };

struct ParallaxSettings {
  ParallaxStudy study = ParallaxStudy::distance;
  double window = 2.0;    // half-size of the integration window on the plane
  double distance = 1.0;  // the source's distance in the angle study
  integrate::AdaptiveOptions integration;  // abs_tolerance is the final tolerance
  double coarse_tolerance = 1e-5;          // the tolerance while the search spans the whole box
};

std::unique_ptr<SweepProblem> make_parallax_problem(const ParallaxSettings& settings);

}  // namespace pbrfit::jobs::sweep
