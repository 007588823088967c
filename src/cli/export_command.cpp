// `pbrfit export RESULT.h5 [--output NAME] [--format hlsl|glsl|cpp] [--member N] [--name F] [--double]`:
// checks that RESULT is a readable pbrfit result as `status` does (the same one-line refusals, exit 2),
// then prints the chosen front member as a function on stdout (jobs/symreg/member_export.hpp; its
// refusals are exit 2, one line) and nothing else; any other failure is exit 3, one line.
#include <charconv>
#include <cstdio>
#include <optional>

#include "exit_on_error.hpp"
#include "summary_reading.hpp"
#include "pbrfit/cli/commands.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/core/quoted_text.hpp"
#include "pbrfit/jobs/symreg/member_export.hpp"

namespace pbrfit::cli {

namespace {

gp::ExportLanguage language_of(const std::string& format) {
  if (format == "glsl") return gp::ExportLanguage::glsl;
  return format == "cpp" ? gp::ExportLanguage::cpp : gp::ExportLanguage::hlsl;
}

// Digits only: "-1", "+2", "1.0" and numbers beyond size_t are refused, naming the option.
std::optional<std::size_t> member_of(const std::string& text) {
  if (text.empty()) return std::nullopt;
  std::size_t member = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), member);
  if (error != std::errc() || end != text.data() + text.size())
    throw InputError({"--member"}, quote(text) + " is not a row of the front (0, 1, 2, ...)");
  return member;
}

jobs::symreg::MemberExport request_of(const ExportOptions& options) {
  jobs::symreg::MemberExport request;
  request.output = options.output;
  request.member = member_of(options.member);
  request.language = language_of(options.format);
  request.function_name = options.name;
  request.cpp_double = options.cpp_double;
  return request;
}

}  // namespace

int export_command(const ExportOptions& options) {
  return exit_on_error([&] {
    const auto summary = read_summary_or_explain(options.result_file);
    const std::string text = jobs::symreg::export_member(options.result_file, summary, request_of(options));
    if (std::fputs(text.c_str(), stdout) < 0 || std::fflush(stdout) != 0) throw RunError("cannot write to stdout");
    return exit_success;
  });
}

}  // namespace pbrfit::cli
