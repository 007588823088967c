#pragma once
// The problems a `sweep` job can name, each with the keys of the job's `objective` section it reads.
// A key of `objective` that the chosen problem does not read is refused (sweep_kind.cpp).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pbrfit/jobs/sweep/sweep_problem.hpp"
#include "pbrfit/spec/schema.hpp"

namespace pbrfit::jobs::sweep {

struct ProblemEntry {
  std::string name;
  std::string summary;
  std::vector<std::string> objective_keys;
  // From the job's `sweep` section (its `objective`, and for `expression` its own keys); throws InputError
  // at the offending key for settings the problem cannot use.
  std::function<std::unique_ptr<SweepProblem>(const spec::Section& sweep)> make;
};

const std::vector<ProblemEntry>& problem_catalogue();
std::vector<std::string> problem_names();
const ProblemEntry& find_problem(const std::string& name);  // std::logic_error for an unknown name

// The schema of `objective`: every key any problem reads, none with a default (problems choose theirs).
spec::Schema objective_schema();

// Problem `expression` (expression_problem.hpp) from the job's `sweep` section.
std::unique_ptr<SweepProblem> make_expression(const spec::Section& sweep);
spec::Schema expression_schema();

// Problems `ltc` and `ltc_ggx` (ltc_problem.hpp) from the job's `sweep` section; `brdf` is the section of
// problem `ltc` that names an expression BRDF or a measured material instead of the built-in families.
std::unique_ptr<SweepProblem> make_ltc(const spec::Section& sweep);
std::unique_ptr<SweepProblem> make_ltc_ggx(const spec::Section& sweep);
spec::Schema brdf_schema();

}  // namespace pbrfit::jobs::sweep
