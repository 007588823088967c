// Problem `expression` from a job file: the domain, the two expression texts, the axes and the parameters
// the job states (expression_problem.hpp).
#include <cmath>

#include "pbrfit/jobs/sweep/expression_problem.hpp"
#include "pbrfit/jobs/sweep/problem_catalogue.hpp"

namespace pbrfit::jobs::sweep {
namespace {

template <class T>
void require(const spec::Located<T>& key, const std::string& why) {
  if (!key.written) key.reject("is required " + why);
}

void read_domain(const ExpressionKeys& e, ExpressionProblemSettings& s) {
  s.domain = e.domain;
  const bool directions = s.domain == ExpressionDomain::sphere || s.domain == ExpressionDomain::hemisphere;
  if (directions) {
    const auto refuse = [](const auto& key) {
      if (key.written) key.reject("does not apply to a sphere or hemisphere (its inputs are wx, wy, wz)");
    };
    refuse(e.inputs), refuse(e.lower), refuse(e.upper);
    s.inputs = {"wx", "wy", "wz"};
    return;
  }
  require(e.inputs, "for an interval or box domain");
  require(e.lower, "for an interval or box domain");
  require(e.upper, "for an interval or box domain");
  s.inputs = e.inputs.value;
  s.lower = e.lower.value;
  s.upper = e.upper.value;
  const std::size_t d = s.inputs.size();
  if (s.domain == ExpressionDomain::interval && d != 1) e.inputs.reject("must name one input for an interval");
  if (s.lower.size() != d || s.upper.size() != d) e.lower.reject("and 'upper' need one value per input");
  for (std::size_t k = 0; k < d; ++k)
    if (!(s.lower[k] < s.upper[k])) e.upper.reject("must exceed 'lower' in every dimension");
}

std::vector<ProblemAxis> stated_axes(const SweepKeys& sweep) {
  std::vector<ProblemAxis> axes;
  for (const AxisKeys& item : sweep.axes.value) {
    const std::string why = "for the axes of problem 'expression'";
    require(item.from, why);
    require(item.to, why);
    require(item.count, why);
    pbrfit::sweep::GridAxis axis{item.name.value, item.from.value, item.to.value, std::size_t(item.count.value),
                                 item.samples.value};
    axes.push_back({axis.name, "axis " + axis.name + " of the expressions", -HUGE_VAL, HUGE_VAL, axis});
  }
  if (axes.empty()) sweep.axes.reject("must state at least one axis (name, from, to, count) for problem 'expression'");
  return axes;
}

void read_parameters(const SweepKeys& sweep, ExpressionProblemSettings& s) {
  for (const ParameterKeys& item : sweep.parameters.value) {
    require(item.lower, "for the parameters of problem 'expression'");
    require(item.upper, "for the parameters of problem 'expression'");
    if (item.model.written) item.model.reject("does not apply to problem 'expression' (it has one model)");
    optimize::Parameter p{item.name.value, item.lower.value, item.upper.value};
    const double start = item.start.written ? item.start.value : 0.5 * (p.lower + p.upper);
    s.parameters.push_back(p);  // the transform and the bounds' checks are applied with the other parameters
    s.start.push_back(start);
  }
  if (s.parameters.empty()) sweep.parameters.reject("must state the model's parameters for problem 'expression'");
}

}  // namespace

spec::Keys<ExpressionKeys> expression_keys() {
  using E = ExpressionKeys;
  spec::Keys<E> k("expression");
  k.choice<ExpressionDomain>("domain",
                             {{"interval", ExpressionDomain::interval}, {"box", ExpressionDomain::box},
                              {"sphere", ExpressionDomain::sphere}, {"hemisphere", ExpressionDomain::hemisphere}},
                             "where target and model are compared", &E::domain)
      .require();
  k.string_list("inputs", 1, 16, "the domain's variables (interval: one; box: one per dimension)", &E::inputs);
  k.number_list("lower", 1, 16, "the domain's lower corner", &E::lower);
  k.number_list("upper", 1, 16, "the domain's upper corner", &E::upper);
  k.string("target", "the function to approximate: an expression of the inputs and the axes", &E::target).require();
  k.string("model", "the approximation: an expression of the inputs, the axes and the parameters", &E::model).require();
  return k;
}

std::unique_ptr<SweepProblem> make_expression(const SweepKeys& sweep) {
  if (!sweep.expression.written)
    sweep.problem.reject("is 'expression', which needs an 'expression' section (domain, target, model)");
  const ExpressionKeys& e = sweep.expression.value;
  const ObjectiveKeys& objective = sweep.objective;
  ExpressionProblemSettings s;
  read_domain(e, s);
  s.axes = stated_axes(sweep);
  read_parameters(sweep, s);
  gp::ExpressionNames names{s.inputs, {}};
  for (const auto& axis : s.axes) names.inputs.push_back(axis.name);
  s.target_text = e.target.value;
  s.model_text = e.model.value;
  s.target = parse_expression_at(e.target, names).program;
  for (const auto& p : s.parameters) names.parameters.push_back(p.name);
  auto model = parse_expression_at(e.model, names);
  s.model = model.program;
  s.parameter_slots = std::move(model.parameter_slots);
  s.p = objective.norm.value;
  s.qmc = objective.qmc.value;
  s.samples = objective.samples.value_or(s.samples);
  s.integration = integration(objective, 1e-6);
  s.coarse_tolerance = coarse_tolerance(objective, s.integration.abs_tolerance, 1e-3);
  if (std::isinf(s.p) && !s.qmc) objective.norm.reject("is Linf, which needs integrator 'qmc' (a maximum is not an integral)");
  if (!s.qmc && s.inputs.size() > 3) e.inputs.reject("at most 3 inputs with integrator 'adaptive'; use 'qmc'");
  return make_expression_problem(std::move(s));
}

}  // namespace pbrfit::jobs::sweep
