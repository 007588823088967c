#pragma once
// Sweep problem `multi_lobe_sg` (Pesce & Iwanicki 2015, section 7.6): N spherical Gaussian lobes in the
// plane of n and v, sharing lambda, fitted to the cosine-weighted GGX response over view angle x roughness
// (alpha = max(r^2, 1e-3)). Error: the relative L2 distance over the whole sphere,
// sqrt(integral (rho - kernel)^2 / integral rho^2), by deterministic QMC with MIS of the GGX and SG lobes
// (brdf/multi_lobe_sg_error.hpp). Models: `free_amplitude` (centre angle, spread, lambda, amplitude) and
// `normalized` (the amplitude makes the kernel integrate to the target's albedo; reported as an output).
#include <cstddef>
#include <memory>

#include "pbrfit/jobs/sweep/sweep_problem.hpp"

namespace pbrfit::jobs::sweep {

struct MultiLobeSgSettings {
  std::size_t lobes = 4;                   // 2 to 16; the course used 4 to 8
  std::size_t samples_per_strategy = 4096;
};

std::unique_ptr<SweepProblem> make_multi_lobe_sg_problem(const MultiLobeSgSettings& settings);

}  // namespace pbrfit::jobs::sweep
