// Chooses the output and member, checks the options, parses the member's expression back and exports
// it after its comment line; the contract is in member_export.hpp.
#include "pbrfit/jobs/symreg/member_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <variant>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/quoted_text.hpp"
#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/export_names.hpp"
#include "pbrfit/jobs/symreg/result_front.hpp"

namespace pbrfit::jobs::symreg {
namespace {

std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + quote(name);
  return out;
}

std::string chosen_output(const std::string& path, const std::string& wanted) {
  const auto outputs = result_outputs(path);
  if (outputs.empty()) throw InputError({path}, "the result has no output groups");
  if (wanted.empty() && outputs.size() > 1)
    throw InputError({path}, "the result has several outputs (" + quoted_list(outputs) + "); choose one with --output");
  if (wanted.empty()) return outputs.front();
  if (std::find(outputs.begin(), outputs.end(), wanted) == outputs.end())
    throw InputError({path}, "no output " + quote(wanted) + " in the result; its outputs: " + quoted_list(outputs));
  return wanted;
}

std::size_t knee_member(const std::string& path, const OutputFront& front) {
  const auto knee = std::find_if(front.members.begin(), front.members.end(), [](const FrontMember& m) { return m.knee; });
  if (knee == front.members.end())
    throw InputError({path}, "the front of " + quote(front.output) + " marks no knee member; choose one with --member");
  return std::size_t(knee - front.members.begin());
}

std::size_t best_test_member(const std::string& path, const OutputFront& front) {
  const auto best = lowest_test_error_member(front);
  if (!best)
    throw InputError({path}, "the front of " + quote(front.output) +
                                 " has no test errors (no test rows: see dataset.test_fraction); choose with --member");
  return *best;
}

std::size_t chosen_member(const std::string& path, const store::ResultSummary& summary, const OutputFront& front,
                          std::optional<std::size_t> wanted, bool by_test_error) {
  const std::size_t count = front.members.size();
  if (count == 0)
    throw InputError({path}, "no front of " + quote(front.output) + " yet: the job has not finished its last stage (" +
                                 store::run_status_name(summary.state) + ", " + std::to_string(summary.items_done) + " of " +
                                 std::to_string(summary.items_total) + " work items done)");
  if (by_test_error) return best_test_member(path, front);
  if (!wanted) return knee_member(path, front);
  if (*wanted >= count)
    throw InputError({path}, "member " + std::to_string(*wanted) + " is out of range: the front of " + quote(front.output) +
                                 " has " + std::to_string(count) + " members (0 to " + std::to_string(count - 1) + ")");
  return *wanted;
}

gp::Program parsed_member(const std::string& path, const OutputFront& front, std::size_t member) {
  const auto parsed = gp::parse_expression(front.members[member].expression, {front.inputs, {}});
  if (const auto* error = std::get_if<gp::ExpressionError>(&parsed))
    throw InputError({path}, "member " + std::to_string(member) + " of " + quote(front.output) +
                                 " does not parse back: " + std::to_string(error->line) + ":" +
                                 std::to_string(error->column) + ": " + error->message);
  return std::get<gp::ParsedExpression>(parsed).program;
}

std::string function_name(const MemberExport& request, const OutputFront& front) {
  if (request.function_name.empty()) return gp::portable_name(front.output);
  if (!gp::is_portable_name(request.function_name))
    throw InputError({"--name"}, quote(request.function_name) +
                                     " is not a name every export language accepts (a letter, then letters, digits "
                                     "and single '_'; no keyword or built-in function)");
  return request.function_name;
}

std::string number_text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::string comment_line(const store::ResultSummary& summary, const OutputFront& front, std::size_t member) {
  const FrontMember& m = front.members[member];
  return "// " + one_line(summary.job_name) + ", output " + one_line(front.output) + ", member " +
         std::to_string(member) + " of " + std::to_string(front.members.size()) + (m.knee ? " (the knee)" : "") +
         ": cost " + number_text(m.cost) + ", RMSE " + number_text(m.rmse) +
         (std::isnan(m.max_abs_error) ? std::string(" (the metric's)")
                                      : ", max abs error " + number_text(m.max_abs_error) + " (in double, on the training rows)") +
         "\n";
}

// The inputs' portable names, made distinct ("a.b" and "a_b" both become a_b: the second a_b_2).
std::vector<std::string> parameter_names(const std::vector<std::string>& inputs) {
  std::vector<std::string> names;
  for (const auto& input : inputs) {
    const std::string base = gp::portable_name(input);
    std::string name = base;
    for (int k = 2; std::find(names.begin(), names.end(), name) != names.end(); ++k)
      name = base + (base.back() == '_' ? "" : "_") + std::to_string(k);
    names.push_back(name);
  }
  return names;
}

gp::ExportOptions export_options(const MemberExport& request, const OutputFront& front) {
  if (request.cpp_double && request.language != gp::ExportLanguage::cpp)
    throw InputError({"--double"}, "only C++ exports can use double (--format cpp)");
  gp::ExportOptions options;
  options.language = request.language;
  options.function_name = function_name(request, front);
  options.input_names = parameter_names(front.inputs);
  options.input_count = front.inputs.size();
  options.cpp_double = request.cpp_double;
  return options;
}

}  // namespace

std::string export_member(const std::string& path, const store::ResultSummary& summary, const MemberExport& request) {
  if (summary.job_kind != "symreg" && summary.job_kind != "brdf_search")
    throw InputError({path}, "not a symbolic-regression or genBRDF result (job kind " + quote(summary.job_kind) +
                                 "); export reads the fronts of symreg and brdf_search results");
  // A BRDF's inputs attribute lists its parameters p0..p3 last: they become arguments of the function.
  const OutputFront front = read_output_front(path, chosen_output(path, request.output));
  const gp::ExportOptions options = export_options(request, front);
  const std::size_t member = chosen_member(path, summary, front, request.member, request.by_test_error);
  return comment_line(summary, front, member) + gp::export_function(parsed_member(path, front, member), options);
}

}  // namespace pbrfit::jobs::symreg
