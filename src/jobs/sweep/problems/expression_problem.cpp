#include "pbrfit/jobs/sweep/expression_problem.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/tree_walker.hpp"
#include "pbrfit/integrate/direction_domain.hpp"
#include "pbrfit/integrate/lp_term.hpp"
#include "pbrfit/integrate/qmc_nodes.hpp"

namespace pbrfit::jobs::sweep {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

bool is_direction(ExpressionDomain d) { return d == ExpressionDomain::sphere || d == ExpressionDomain::hemisphere; }

double root_of(double integral, double p) { return p == 1.0 ? integral : std::pow(std::max(integral, 0.0), 1.0 / p); }

// One cell: the axis values fixed, the target tabulated at the QMC nodes (or evaluated point by point).
class ExpressionCell final : public CellTarget {
 public:
  ExpressionCell(const ExpressionProblemSettings& s, const integrate::WeightedNodes* nodes, std::span<const double> cell)
      : s_(s), nodes_(nodes), cell_(cell.begin(), cell.end()), row_(s.inputs.size() + cell.size()) {
    std::copy(cell_.begin(), cell_.end(), row_.begin() + std::ptrdiff_t(s.inputs.size()));
    if (s_.qmc) tabulate();
    norm_ = s_.qmc ? qmc_distance(std::vector<double>(nodes_->size(), 0.0))
                   : adaptive_distance([](std::span<const double>) { return 0.0; }, s_.integration.abs_tolerance);
  }

  pbrfit::sweep::CellProblem problem(std::size_t, const std::vector<optimize::Parameter>& parameters) const override {
    pbrfit::sweep::CellProblem out;
    out.parameters = optimize::ParameterSpace(parameters);
    out.default_start = s_.start;
    out.error = [this](std::span<const double> x, double tolerance) { return model_distance(x, tolerance); };
    return out;
  }

  std::vector<double> outputs(std::size_t, std::span<const double> x) const override {
    const double error = model_distance(x, s_.integration.abs_tolerance);
    return {norm_, norm_ > 0.0 ? error / norm_ : std::numeric_limits<double>::quiet_NaN()};
  }

 private:
  void tabulate() {
    gp::Dataset data;
    data.inputs.resize(Eigen::Index(nodes_->size()), Eigen::Index(row_.size()));
    for (std::size_t i = 0; i < nodes_->size(); ++i) {
      const auto node = nodes_->node(i);
      for (std::size_t k = 0; k < node.size(); ++k) data.inputs(Eigen::Index(i), Eigen::Index(k)) = node[k];
      for (std::size_t k = 0; k < cell_.size(); ++k)
        data.inputs(Eigen::Index(i), Eigen::Index(node.size() + k)) = cell_[k];
    }
    data.target = Eigen::ArrayXd::Zero(data.inputs.rows());
    interpreter_ = std::make_unique<gp::BatchInterpreter<double>>(data);
    target_values_.resize(nodes_->size());
    model_values_.resize(nodes_->size());
    interpreter_->evaluate(s_.target, target_values_);
  }

  double model_distance(std::span<const double> x, double tolerance) const {
    gp::Program model = s_.model;
    gp::set_parameters(model, s_.parameter_slots, x);
    if (s_.qmc) {
      interpreter_->evaluate(model, model_values_);
      return qmc_distance(model_values_);
    }
    return adaptive_distance([&](std::span<const double> row) { return gp::walk_tree<double>(model, row); }, tolerance);
  }

  double qmc_distance(std::span<const double> model) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < model.size(); ++i) {
      const double d = target_values_[i] - model[i];
      if (!std::isfinite(d)) return infinity;
      sum = std::isinf(s_.p) ? std::max(sum, std::abs(d)) : sum + nodes_->weights[i] * integrate::lp_term(d, s_.p);
    }
    return std::isinf(s_.p) ? sum : root_of(sum, s_.p);
  }

  // The distance between the target and `model` (a function of a full input row) by adaptive cubature.
  template <class Model>
  double adaptive_distance(const Model& model, double tolerance) const {
    integrate::AdaptiveOptions options = s_.integration;
    options.abs_tolerance = tolerance;
    bool finite = true;
    const auto integrand = [&](std::span<const double> point) {
      std::vector<double>& row = row_;
      std::copy(point.begin(), point.end(), row.begin());
      const double d = gp::walk_tree<double>(s_.target, row) - model(row);
      if (!std::isfinite(d)) finite = false;
      return std::array<double, 1>{std::isfinite(d) ? integrate::lp_term(d, s_.p) : 0.0};
    };
    const double integral = adaptive_integral(integrand, options);
    return finite ? root_of(integral, s_.p) : infinity;
  }

  template <class Integrand>
  double adaptive_integral(const Integrand& f, const integrate::AdaptiveOptions& options) const {
    if (is_direction(s_.domain)) {
      const double z_min = s_.domain == ExpressionDomain::hemisphere ? 0.0 : -1.0;
      const auto on_direction = [&](const integrate::UnitDirection& w) { return f(std::span<const double>(w)); };
      return integrate::integrate_over_directions<1>(on_direction, z_min, 1.0, 4, options).value[0];
    }
    switch (s_.lower.size()) {
      case 1: return in_box<1>(f, options);
      case 2: return in_box<2>(f, options);
      default: return in_box<3>(f, options);
    }
  }

  template <int Dim, class Integrand>
  double in_box(const Integrand& f, const integrate::AdaptiveOptions& options) const {
    integrate::Box<Dim> box;
    for (int k = 0; k < Dim; ++k) box.lo[std::size_t(k)] = s_.lower[std::size_t(k)], box.hi[std::size_t(k)] = s_.upper[std::size_t(k)];
    const auto on_point = [&](const std::array<double, Dim>& x) { return f(std::span<const double>(x)); };
    return integrate::integrate_adaptive<Dim, 1>(on_point, std::span<const integrate::Box<Dim>>(&box, 1), options).value[0];
  }

  const ExpressionProblemSettings& s_;
  const integrate::WeightedNodes* nodes_;
  std::vector<double> cell_;
  mutable std::vector<double> row_;  // inputs then axis values; scratch of the calling thread
  std::unique_ptr<gp::BatchInterpreter<double>> interpreter_;
  std::vector<double> target_values_;
  mutable std::vector<double> model_values_;
  double norm_ = 0.0;
};

class ExpressionProblem final : public SweepProblem {
 public:
  explicit ExpressionProblem(ExpressionProblemSettings s) : s_(std::move(s)) {
    if (!s_.qmc) return;
    nodes_ = is_direction(s_.domain) ? integrate::direction_qmc_nodes(s_.samples, s_.domain == ExpressionDomain::hemisphere)
                                     : integrate::box_qmc_nodes(s_.lower, s_.upper, s_.samples);
  }

  std::string description() const override { return "the model " + s_.model_text + " fitted to " + s_.target_text; }
  std::vector<ProblemAxis> axes() const override { return s_.axes; }
  std::vector<ModelInfo> models() const override {
    const std::string norm = std::isinf(s_.p) ? "Linf" : "L" + std::to_string(int(s_.p));
    return {{"model", s_.model_text, s_.parameters, norm + " distance between target and model over the domain",
             {{"target_norm", "the " + norm + " norm of the target over the domain"},
              {"relative_error", "error / target_norm", "error"}}}};
  }
  std::map<std::string, std::string> attributes() const override {
    static const char* domains[] = {"interval", "box", "sphere", "hemisphere"};
    std::string inputs;
    for (const auto& name : s_.inputs) inputs += (inputs.empty() ? "" : ", ") + name;
    return {{"target", s_.target_text},
            {"model", s_.model_text},
            {"domain", domains[int(s_.domain)]},
            {"inputs", inputs},
            {"integrator", s_.qmc ? "QMC, " + std::to_string(s_.samples) + " points" +
                                        (is_direction(s_.domain) ? " per strategy (uniform and cosine, MIS)" : "")
                                  : "globally adaptive Gauss-Kronrod cubature"}};
  }
  optimize::ToleranceSchedule tolerance_schedule() const override {
    if (s_.qmc) return optimize::ToleranceSchedule::constant(0.0);
    return {s_.coarse_tolerance, s_.integration.abs_tolerance, 1e-3, 4};
  }
  std::unique_ptr<CellTarget> target(std::span<const double> c) const override {
    return std::make_unique<ExpressionCell>(s_, &nodes_, c);
  }

 private:
  ExpressionProblemSettings s_;
  integrate::WeightedNodes nodes_;
};

}  // namespace

std::unique_ptr<SweepProblem> make_expression_problem(ExpressionProblemSettings settings) {
  return std::make_unique<ExpressionProblem>(std::move(settings));
}

}  // namespace pbrfit::jobs::sweep
