#pragma once
// Reading the keys of a sweep's `objective` section that several problems share, each with the default the
// calling problem chooses when the key is not written; and expression texts of the job, parsed at their key.
#include <cstddef>

#include "pbrfit/gp/expression_parser.hpp"
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

// The expression text at `key` of section s; a parse error is an InputError at the key naming its line and
// column within the text.
gp::ParsedExpression parse_expression_at(const spec::Section& s, const char* key, const gp::ExpressionNames& names);

}  // namespace pbrfit::jobs::sweep
