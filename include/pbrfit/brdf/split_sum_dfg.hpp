#pragma once
// The split-sum environment BRDF ("DFG") terms of GGX specular (Karis 2013, Narkowicz 2014,
// Pesce & Iwanicki 2015 section 5.3), integrated adaptively over light directions above the horizon:
//   scale = integral of (f/F) (1 - (1 - v.h)^5) (n.l) dl,   bias = integral of (f/F) (1 - v.h)^5 (n.l) dl.
// scale + bias is the directional albedo E(n.v) of the single-scattering lobe with F = 1.
#include <cstddef>

#include "pbrfit/brdf/ggx.hpp"
#include "pbrfit/integrate/adaptive_cubature.hpp"

namespace pbrfit::brdf {

struct DfgEntry {
  double scale = 0.0;
  double bias = 0.0;
  double error_estimate = 0.0;   // absolute; sum over tiles of the larger component error, bounds both
  std::size_t evaluations = 0;   // integrand evaluations spent
  bool converged = false;
};

// One table entry. n_dot_v in [0, 1], alpha >= 0 (alpha == 0 is the mirror limit, computed in closed form
// with evaluations = 0); throws std::invalid_argument outside that domain.
DfgEntry integrate_dfg(double n_dot_v, double alpha, SmithVisibility visibility,
                       const integrate::AdaptiveOptions& options);

struct AverageAlbedo {
  double value = 0.0;            // E_avg = 2 * integral over mu in [0,1] of E(mu) mu
  double error_estimate = 0.0;
  std::size_t evaluations = 0;   // including the inner integrals
  bool converged = false;
};

// Kulla-Conty average albedo of the single-scattering lobe (F = 1) for one alpha: a 1-D adaptive integral
// over mu whose samples are integrate_dfg calls at a tenth of the tolerance. error_estimate = outer estimate
// + largest inner estimate; options.max_evaluations limits outer samples and each inner integral separately.
AverageAlbedo integrate_average_albedo(double alpha, SmithVisibility visibility,
                                       const integrate::AdaptiveOptions& options);

}  // namespace pbrfit::brdf
