#pragma once
// Reading the keys of a sweep's `objective` section that several problems share, each with the default the
// calling problem chooses when the key is not written.
#include <cstddef>

#include "pbrfit/integrate/adaptive_cubature.hpp"
#include "pbrfit/spec/schema.hpp"

namespace pbrfit::jobs::sweep {

std::size_t count_or(const spec::Section& objective, const char* key, std::size_t fallback);
// `norm`: L1, L2 (the default), L3, Linf as p = 1, 2, 3, +inf.
double norm_p(const spec::Section& objective);
// `tolerance` (or `tolerance_default`) and `max_evaluations` as adaptive-cubature options.
integrate::AdaptiveOptions integration(const spec::Section& objective, double tolerance_default);
// `coarse_tolerance`, at least the integration tolerance (InputError otherwise).
double coarse_tolerance(const spec::Section& objective, double final_tolerance, double fallback);

}  // namespace pbrfit::jobs::sweep
