#pragma once
// The problems a `sweep` job can name, each with the keys of the job's `objective` section it reads.
// A key of `objective` that the chosen problem does not read is refused (sweep_kind.cpp).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pbrfit/jobs/sweep/sweep_problem.hpp"
#include "pbrfit/jobs/sweep/sweep_keys.hpp"
#include "pbrfit/spec/schema.hpp"

namespace pbrfit::jobs::sweep {

struct ProblemEntry {
  std::string name;
  std::string summary;
  std::vector<std::string> objective_keys;
  // From the keys of the job's `sweep` section (its `objective`, and the problem's own sections); throws
  // InputError at the offending key for settings the problem cannot use.
  std::function<std::unique_ptr<SweepProblem>(const SweepKeys& sweep)> make;
};

const std::vector<ProblemEntry>& problem_catalogue();
std::vector<std::string> problem_names();
const ProblemEntry& find_problem(const std::string& name);  // std::logic_error for an unknown name

// The schema of `objective`: every key any problem reads, none with a default (problems choose theirs).
spec::Schema objective_schema();

// Problem `expression` (expression_problem.hpp) from the job's keys (expression_settings.cpp).
std::unique_ptr<SweepProblem> make_expression(const SweepKeys& sweep);

// Problems `ltc` and `ltc_ggx` (ltc_problem.hpp) from the job's keys (ltc_settings.cpp); `brdf` is the
// section of problem `ltc` that names an expression BRDF or a measured material instead of the families.
std::unique_ptr<SweepProblem> make_ltc(const SweepKeys& sweep);
std::unique_ptr<SweepProblem> make_ltc_ggx(const SweepKeys& sweep);

}  // namespace pbrfit::jobs::sweep
