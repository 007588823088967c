// `pbrfit export RESULT.h5 ...`: checks that RESULT is a readable pbrfit result as `status` does (the same
// one-line refusals, exit 2), then
//  - for a lut, sweep or ebrdf result, writes one of its tables as a texture or source file
//    (jobs/table_export.hpp makes the texture, texture/format.hpp encodes it) to --out, atomically, and
//    prints one line naming the file and what it holds; what cannot be exported (no such table, a format
//    that cannot hold it, an incomplete result, a bad option) is exit 2, one line;
//  - for a symreg or brdf_search result, prints the chosen front member as a function on stdout
//    (jobs/symreg/member_export.hpp; its refusals are exit 2, one line) and nothing else.
// Any other failure is exit 3, one line.
#include <cctype>
#include <charconv>
#include <cstdio>
#include <optional>

#include "exit_on_error.hpp"
#include "summary_reading.hpp"
#include "pbrfit/cli/commands.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/core/quoted_text.hpp"
#include "pbrfit/jobs/symreg/member_export.hpp"
#include "pbrfit/jobs/table_export.hpp"
#include "pbrfit/store/atomic_file.hpp"
#include "pbrfit/texture/format.hpp"

namespace pbrfit::cli {

namespace {

gp::ExportLanguage language_of(const std::string& format) {
  if (format == "glsl") return gp::ExportLanguage::glsl;
  if (format == "cpp") return gp::ExportLanguage::cpp;
  if (format.empty() || format == "hlsl") return gp::ExportLanguage::hlsl;
  throw InputError({"--format"}, quote(format) + " is not a language of a front member's function (hlsl, glsl, cpp)");
}

bool holds_tables(const std::string& kind) { return kind == "lut" || kind == "sweep" || kind == "ebrdf"; }

std::string format_names() {
  std::string out;
  for (auto f : texture::all_formats()) out += (out.empty() ? "" : ", ") + std::string(texture::format_name(f));
  return out;
}

std::vector<std::string> comma_list(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size() && !text.empty()) {
    const std::size_t comma = text.find(',', start);
    out.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

// A table's symbol prefix from its name: "ggx/level0/ltc_1" -> "LTC_1_".
std::string default_prefix(const std::string& table) {
  std::string name = table.substr(table.rfind('/') + 1);
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? char(std::toupper(static_cast<unsigned char>(c))) : '_';
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "T" + out;
  return out + "_";
}

std::string default_path(const ExportOptions& o, const std::string& table, texture::Format format) {
  std::string stem = o.result_file;
  if (stem.size() > 3 && stem.ends_with(".h5")) stem.resize(stem.size() - 3);
  const std::string model = o.model.empty() ? "" : "." + o.model;
  return stem + model + "." + table + std::string(texture::file_extension(format));
}

ExitCode export_table(const ExportOptions& o, const store::ResultSummary& summary) {
  if (o.format.empty()) throw InputError({"--format"}, "is needed to export a table: one of " + format_names());
  const auto format = texture::format_named(o.format);
  if (!format) throw InputError({"--format"}, quote(o.format) + " is not a table format (" + format_names() + ")");
  if (o.precision != "float" && o.precision != "half")
    throw InputError({"--precision"}, quote(o.precision) + " is neither float nor half");
  for (const char* option : {"--output", "--member", "--name", "--double"}) {
    const bool given = (std::string(option) == "--output" && !o.output.empty()) ||
                       (std::string(option) == "--member" && !o.member.empty()) ||
                       (std::string(option) == "--name" && !o.name.empty()) || (std::string(option) == "--double" && o.cpp_double);
    if (given) throw InputError({option}, "applies to a front member's function, not to a table");
  }
  jobs::TableRequest request{o.table, o.model, comma_list(o.channels), o.u_axis, o.flip_v};
  const texture::Texture t = jobs::table_texture(o.result_file, summary, request);
  const std::string table = o.table.empty() ? t.name.substr(t.name.rfind('/') + 1) : o.table;
  texture::EncodeOptions options;
  options.precision = o.precision == "half" ? texture::Precision::f16 : texture::Precision::f32;
  options.prefix = o.prefix.empty() ? default_prefix(t.name) : o.prefix;
  Bytes bytes;
  try {
    bytes = texture::encode(t, *format, options);
  } catch (const std::invalid_argument& e) {
    throw InputError({o.result_file}, "cannot export " + t.name + ": " + e.what());
  }
  const std::string path = o.out.empty() ? default_path(o, table, *format) : o.out;
  store::replace_file_atomically(path, std::as_bytes(std::span(bytes)));
  std::printf("wrote %s: %s, %zu x %zu%s%s%s, %zu channel%s (", path.c_str(), t.name.c_str(), t.width, t.height,
              t.depth > 1 ? (" x " + std::to_string(t.depth)).c_str() : "",
              t.layers > 1 ? (", " + std::to_string(t.layers) + " layers").c_str() : "",
              t.levels > 1 ? (", " + std::to_string(t.levels) + " mip levels").c_str() : "", t.channels.size(),
              t.channels.size() == 1 ? "" : "s");
  for (std::size_t c = 0; c < t.channels.size(); ++c) std::printf("%s%s", c ? ", " : "", t.channels[c].c_str());
  std::printf("), %s\n", *format == texture::Format::hdr ? "RGBE" : *format == texture::Format::png ? "16-bit"
                                                           : o.precision == "half" ? "float16" : "float32");
  if (std::fflush(stdout) != 0) throw RunError("cannot write to stdout");
  return exit_success;
}

// Digits only (or "test", handled by request_of): "-1", "+2", "1.0" and numbers beyond size_t are refused,
// naming the option.
std::optional<std::size_t> member_of(const std::string& text) {
  if (text.empty() || text == "test") return std::nullopt;
  std::size_t member = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), member);
  if (error != std::errc() || end != text.data() + text.size())
    throw InputError({"--member"}, quote(text) + " is not a row of the front (0, 1, 2, ...) or 'test'");
  return member;
}

jobs::symreg::MemberExport request_of(const ExportOptions& options) {
  jobs::symreg::MemberExport request;
  request.output = options.output;
  request.member = member_of(options.member);
  request.by_test_error = options.member == "test";
  request.language = language_of(options.format);
  request.function_name = options.name;
  request.cpp_double = options.cpp_double;
  return request;
}

}  // namespace

int export_command(const ExportOptions& options) {
  return exit_on_error([&] {
    const auto summary = read_summary_or_explain(options.result_file);
    if (holds_tables(summary.job_kind)) return export_table(options, summary);
    const std::string text = jobs::symreg::export_member(options.result_file, summary, request_of(options));
    if (std::fputs(text.c_str(), stdout) < 0 || std::fflush(stdout) != 0) throw RunError("cannot write to stdout");
    return exit_success;
  });
}

}  // namespace pbrfit::cli
