#include "pbrfit/jobs/sweep/objective_keys.hpp"

#include <algorithm>
#include <limits>
#include <string>

namespace pbrfit::jobs::sweep {

std::size_t count_or(const spec::Section& s, const char* key, std::size_t fallback) {
  return s.given(key) ? std::size_t(s.get_int(key)) : fallback;
}

double norm_p(const spec::Section& s) {
  if (!s.given("norm")) return 2.0;
  const std::string& norm = s.get_string("norm");
  return norm == "L1" ? 1.0 : norm == "L3" ? 3.0 : norm == "Linf" ? std::numeric_limits<double>::infinity() : 2.0;
}

integrate::AdaptiveOptions integration(const spec::Section& s, double tolerance_default) {
  integrate::AdaptiveOptions options;
  options.abs_tolerance = s.given("tolerance") ? s.get_number("tolerance") : tolerance_default;
  if (s.given("max_evaluations")) options.max_evaluations = std::size_t(s.get_int("max_evaluations"));
  return options;
}

gp::ParsedExpression parse_expression_at(const spec::Section& e, const char* key, const gp::ExpressionNames& names) {
  const auto result = gp::parse_expression(e.get_string(key), names);
  if (const auto* error = std::get_if<gp::ExpressionError>(&result))
    e.reject(key, "has an error at line " + std::to_string(error->line) + ", column " + std::to_string(error->column) +
                      " of its expression: " + error->message);
  return std::get<gp::ParsedExpression>(result);
}

double coarse_tolerance(const spec::Section& s, double final_tolerance, double fallback) {
  const double coarse = s.given("coarse_tolerance") ? s.get_number("coarse_tolerance") : std::max(fallback, final_tolerance);
  if (coarse < final_tolerance) s.reject("coarse_tolerance", "must be at least 'tolerance'");
  return coarse;
}

}  // namespace pbrfit::jobs::sweep
