#include "pbrfit/jobs/symreg/front_measures.hpp"

#include <cmath>
#include <limits>

#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/constant_fitting.hpp"
#include "pbrfit/gp/expression_printer.hpp"
#include "pbrfit/gp/live_code.hpp"

namespace pbrfit::jobs::symreg {
namespace {

void errors_of(const gp::Program& program, const gp::Dataset& data, double& rmse, double& max_abs) {
  const auto out = predictions(program, data);
  double sum = 0.0, weights = 0.0;
  max_abs = 0.0;
  for (std::size_t r = 0; r < out.size(); ++r) {
    const double d = out[r] - data.target[Eigen::Index(r)], w = data.weight(r);
    sum += w * d * d;
    weights += w;
    if (w > 0) max_abs = std::isfinite(d) ? std::max(max_abs, std::abs(d)) : std::numeric_limits<double>::infinity();
  }
  rmse = std::sqrt(sum / weights);
}

}  // namespace

std::vector<double> predictions(const gp::Program& program, const gp::Dataset& data) {
  gp::BatchInterpreter<double> interpreter(data);
  std::vector<double> out(data.rows());
  interpreter.evaluate(program, out);
  return out;
}

ProgramMeasures measure_program(const gp::Program& program, const gp::Dataset& train, const gp::Dataset& test) {
  ProgramMeasures m;
  errors_of(program, train, m.rmse, m.max_abs_error);
  double unused = 0.0;
  m.test_rmse = std::numeric_limits<double>::quiet_NaN();
  if (test.rows() > 0) errors_of(program, test, m.test_rmse, unused);
  m.operations = live_operations(program);
  return m;
}

std::uint32_t live_operations(const gp::Program& program) {
  const auto live = gp::live_instructions(program);
  std::uint32_t count = 0;
  for (std::size_t i = 0; i < program.length; ++i) count += live.test(i) && program.code[i].op != gp::Opcode::identity;
  return count;
}

std::string expression_text(const gp::Program& program, const gp::ExpressionNames& names) {
  std::string text = gp::print_expression(program, names);
  for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at)) text.replace(at, 1, "; ");
  return text;
}

std::string constants_text(const gp::Program& program) {
  std::string text;
  for (const auto& slot : gp::live_constant_slots(program))
    text += (text.empty() ? "" : ", ") + gp::shortest_decimal(program.code[slot.instruction].constants[slot.operand]);
  return text;
}

}  // namespace pbrfit::jobs::symreg
