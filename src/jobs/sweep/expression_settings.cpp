// Problem `expression` from a job file: the domain, the two expression texts, the axes and the parameters
// the job states (expression_problem.hpp).
#include <cmath>

#include "pbrfit/jobs/sweep/expression_problem.hpp"
#include "pbrfit/jobs/sweep/objective_keys.hpp"
#include "pbrfit/jobs/sweep/problem_catalogue.hpp"

namespace pbrfit::jobs::sweep {
namespace {

ExpressionDomain domain_from(const std::string& name) {
  if (name == "box") return ExpressionDomain::box;
  if (name == "sphere") return ExpressionDomain::sphere;
  if (name == "hemisphere") return ExpressionDomain::hemisphere;
  return ExpressionDomain::interval;
}

void read_domain(const spec::Section& e, ExpressionProblemSettings& s) {
  s.domain = domain_from(e.get_string("domain"));
  const bool directions = s.domain == ExpressionDomain::sphere || s.domain == ExpressionDomain::hemisphere;
  if (directions) {
    for (const char* key : {"inputs", "lower", "upper"})
      if (e.given(key)) e.reject(key, "does not apply to a sphere or hemisphere (its inputs are wx, wy, wz)");
    s.inputs = {"wx", "wy", "wz"};
    return;
  }
  for (const char* key : {"inputs", "lower", "upper"})
    if (!e.given(key)) e.reject(key, "is required for an interval or box domain");
  s.inputs = e.get_string_list("inputs");
  s.lower = e.get_number_list("lower");
  s.upper = e.get_number_list("upper");
  const std::size_t d = s.inputs.size();
  if (s.domain == ExpressionDomain::interval && d != 1) e.reject("inputs", "must name one input for an interval");
  if (s.lower.size() != d || s.upper.size() != d) e.reject("lower", "and 'upper' need one value per input");
  for (std::size_t k = 0; k < d; ++k)
    if (!(s.lower[k] < s.upper[k])) e.reject("upper", "must exceed 'lower' in every dimension");
}

std::vector<ProblemAxis> stated_axes(const spec::Section& sweep) {
  std::vector<ProblemAxis> axes;
  for (const auto& item : sweep.get_section_list("axes")) {
    for (const char* key : {"from", "to", "count"})
      if (!item.given(key)) item.reject(key, "is required for the axes of problem 'expression'");
    pbrfit::sweep::GridAxis axis{item.get_string("name"), item.get_number("from"), item.get_number("to"),
                                 std::size_t(item.get_int("count")),
                                 item.given("samples") && item.get_string("samples") == "centres"
                                     ? pbrfit::sweep::Placement::centres
                                     : pbrfit::sweep::Placement::edges};
    axes.push_back({axis.name, "axis " + axis.name + " of the expressions", -HUGE_VAL, HUGE_VAL, axis});
  }
  if (axes.empty()) sweep.reject("axes", "must state at least one axis (name, from, to, count) for problem 'expression'");
  return axes;
}

void read_parameters(const spec::Section& sweep, ExpressionProblemSettings& s) {
  for (const auto& item : sweep.get_section_list("parameters")) {
    for (const char* key : {"lower", "upper"})
      if (!item.given(key)) item.reject(key, "is required for the parameters of problem 'expression'");
    if (item.given("model")) item.reject("model", "does not apply to problem 'expression' (it has one model)");
    optimize::Parameter p{item.get_string("name"), item.get_number("lower"), item.get_number("upper")};
    const double start = item.given("start") ? item.get_number("start") : 0.5 * (p.lower + p.upper);
    s.parameters.push_back(p);  // the transform and the bounds' checks are applied with the other parameters
    s.start.push_back(start);
  }
  if (s.parameters.empty()) sweep.reject("parameters", "must state the model's parameters for problem 'expression'");
}

}  // namespace

spec::Schema expression_schema() {
  spec::Schema s("expression");
  s.choice("domain", {"interval", "box", "sphere", "hemisphere"}, "where target and model are compared").require();
  s.string_list("inputs", 1, 16, "the domain's variables (interval: one; box: one per dimension)");
  s.number_list("lower", 1, 16, "the domain's lower corner");
  s.number_list("upper", 1, 16, "the domain's upper corner");
  s.string("target", "the function to approximate: an expression of the inputs and the axes").require();
  s.string("model", "the approximation: an expression of the inputs, the axes and the parameters").require();
  return s;
}

std::unique_ptr<SweepProblem> make_expression(const spec::Section& sweep) {
  if (!sweep.has("expression")) sweep.reject("problem", "is 'expression', which needs an 'expression' section (domain, target, model)");
  const auto& e = sweep.get_section("expression");
  const auto& objective = sweep.get_section("objective");
  ExpressionProblemSettings s;
  read_domain(e, s);
  s.axes = stated_axes(sweep);
  read_parameters(sweep, s);
  gp::ExpressionNames names{s.inputs, {}};
  for (const auto& axis : s.axes) names.inputs.push_back(axis.name);
  s.target_text = e.get_string("target");
  s.model_text = e.get_string("model");
  s.target = parse_expression_at(e, "target", names).program;
  for (const auto& p : s.parameters) names.parameters.push_back(p.name);
  auto model = parse_expression_at(e, "model", names);
  s.model = model.program;
  s.parameter_slots = std::move(model.parameter_slots);
  s.p = norm_p(objective);
  s.qmc = objective.given("integrator") && objective.get_string("integrator") == "qmc";
  s.samples = count_or(objective, "samples", s.samples);
  s.integration = integration(objective, 1e-6);
  s.coarse_tolerance = coarse_tolerance(objective, s.integration.abs_tolerance, 1e-3);
  if (std::isinf(s.p) && !s.qmc) objective.reject("norm", "is Linf, which needs integrator 'qmc' (a maximum is not an integral)");
  if (!s.qmc && s.inputs.size() > 3) e.reject("inputs", "at most 3 inputs with integrator 'adaptive'; use 'qmc'");
  return make_expression_problem(std::move(s));
}

}  // namespace pbrfit::jobs::sweep
