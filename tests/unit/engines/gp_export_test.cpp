#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

#include "gp_test_support.hpp"
#include "pbrfit/gp/batch_interpreter.hpp"
#include "pbrfit/gp/export.hpp"
#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/tree_walker.hpp"

using namespace pbrfit::gp;
namespace fs = std::filesystem;

namespace {

// Every operator, constants of both signs, a shared subexpression and an identity.
constexpr const char* every_operator =
    "t = fma(x, 0.5, -y)\n"
    "u = max(min(t, 2), -2.25)\n"
    "v = saturate(u) + abs(t) - sqrt(x) * rsqrt(y + 3) + exp(u) / exp2(-u) + log(y) - log2(x)\n"
    "v + pow(x, 1.5) + sin(t) * cos(y) + neg(u) * 0.001 + 1e-07 - 123456.7";

Program every_operator_program() {
  const auto parsed = parse_expression(every_operator, {{"x", "y"}, {}});
  REQUIRE(std::holds_alternative<ParsedExpression>(parsed));
  return std::get<ParsedExpression>(parsed).program;
}

struct TempDir {
  TempDir() : path(fs::temp_directory_path() / ("pbrfit_gp_export_" + std::to_string(::getpid()))) {
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  fs::path path;
};

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

bool tool_available(const char* tool) {
  return std::system((std::string("command -v ") + tool + " > /dev/null 2>&1").c_str()) == 0;
}

// A main() that reads rows of hex floats from stdin and prints the exported function's value per row.
std::string driver(std::size_t programs, std::size_t inputs) {
  std::ostringstream text;
  text << "\n#include <cstdio>\nint main() {\n  float x[" << inputs << "];\n  for (;;) {\n";
  for (std::size_t k = 0; k < inputs; ++k) text << "    if (std::scanf(\"%a\", &x[" << k << "]) != 1) return 0;\n";
  for (std::size_t p = 0; p < programs; ++p) {
    text << "    std::printf(\"%a\\n\", double(f" << p << "(";
    for (std::size_t k = 0; k < inputs; ++k) text << (k ? ", " : "") << "x[" << k << "]";
    text << ")));\n";
  }
  text << "  }\n}\n";
  return text.str();
}

}  // namespace

TEST_CASE("Float literals: shortest digits of the float, suffixes, parenthesized negatives", "[gp]") {
  CHECK(number_literal(0.1, ExportLanguage::hlsl) == "0.1f");
  CHECK(number_literal(0.1, ExportLanguage::glsl) == "0.1");
  CHECK(number_literal(3.0, ExportLanguage::cpp) == "3.0f");
  CHECK(number_literal(-2.5e-8, ExportLanguage::glsl) == "(-2.5e-08)");
  CHECK(number_literal(0.1, ExportLanguage::cpp, true) == "0.1");
  CHECK(number_literal(1.0 / 3.0, ExportLanguage::cpp, true) == "0.3333333333333333");
  CHECK(number_literal(1.0 / 3.0, ExportLanguage::cpp) == "0.33333334f");
  CHECK(number_literal(1e300, ExportLanguage::hlsl) == "(1.0f / 0.0f)");  // what the float interpreter sees
}

TEST_CASE("The exported shader text uses the language's built-ins and protected forms", "[gp]") {
  ExportOptions options;
  options.input_names = {"x", "y"};
  options.function_name = "fitted";
  const std::string hlsl = export_function(every_operator_program(), options);
  CHECK(hlsl.rfind("float fitted(float x, float y) {\n", 0) == 0);
  for (const char* piece :
       {"mad(x, 0.5f, t0)", "(-2.25f)", "saturate(", "rsqrt(abs(", "log(abs(y))", "exp2(1.5f * log2(abs(x)))"}) {
    CAPTURE(piece, hlsl);
    CHECK(hlsl.find(piece) != std::string::npos);
  }
  options.language = ExportLanguage::glsl;
  const std::string glsl = export_function(every_operator_program(), options);
  for (const char* piece : {"inversesqrt(abs(", "clamp(", "x * 0.5 + "}) CHECK(glsl.find(piece) != std::string::npos);
}

TEST_CASE("The C++ export compiles and computes what the interpreters compute", "[gp]") {
  if (!tool_available("c++")) SKIP("no c++ compiler on PATH");
  std::vector<Program> programs{every_operator_program()};
  for (std::uint64_t i = 0; i < 20; ++i) programs.push_back(gp_test::random_program(gp_test::wide_shape(2), 21, i));
  const Dataset dataset = gp_test::sampled_dataset(200, 2, 0.05, 3.0, [](auto) { return 0.0; });
  TempDir dir;
  std::string source;
  for (std::size_t p = 0; p < programs.size(); ++p) {
    ExportOptions options;
    options.language = ExportLanguage::cpp;
    options.function_name = "f" + std::to_string(p);
    options.input_count = 2;
    const std::string text = export_function(programs[p], options);
    source += p == 0 ? text : text.substr(text.find("inline"));
  }
  write(dir.path / "model.cpp", source + driver(programs.size(), 2));
  std::string rows;
  for (std::size_t r = 0; r < dataset.rows(); ++r) {
    char line[128];
    std::snprintf(line, sizeof line, "%a %a\n", double(float(dataset.inputs(r, 0))),
                  double(float(dataset.inputs(r, 1))));
    rows += line;
  }
  write(dir.path / "rows.txt", rows);
  const std::string build = "c++ -std=c++17 -O2 -ffp-contract=off -o " + (dir.path / "model").string() + " " +
                            (dir.path / "model.cpp").string() + " 2> " + (dir.path / "build.log").string();
  REQUIRE(std::system(build.c_str()) == 0);
  const std::string run = (dir.path / "model").string() + " < " + (dir.path / "rows.txt").string() + " > " +
                          (dir.path / "out.txt").string();
  REQUIRE(std::system(run.c_str()) == 0);
  std::ifstream out(dir.path / "out.txt");
  BatchInterpreter<float> interpreter(dataset);
  std::vector<float> batch(dataset.rows());
  std::vector<float> walked(dataset.rows());
  std::vector<std::vector<float>> compiled(programs.size(), std::vector<float>(dataset.rows()));
  for (std::size_t r = 0; r < dataset.rows(); ++r) {
    for (auto& values : compiled) {
      std::string word;
      out >> word;
      values[r] = std::strtof(word.c_str(), nullptr);
    }
  }
  std::size_t far_from_interpreter = 0;
  for (std::size_t p = 0; p < programs.size(); ++p) {
    interpreter.evaluate(programs[p], batch);
    walk_tree<float>(programs[p], dataset, walked);
    for (std::size_t r = 0; r < dataset.rows(); ++r) {
      const float c = compiled[p][r];
      CAPTURE(p, r, c, walked[r]);
      CHECK((std::memcmp(&c, &walked[r], sizeof c) == 0 || (c != c && walked[r] != walked[r])));
      const bool near = std::abs(double(c) - double(batch[r])) <= 1e-3 * (1.0 + std::abs(double(c)));
      far_from_interpreter += !(near || c == batch[r] || (c != c && batch[r] != batch[r]));
    }
  }
  CHECK(far_from_interpreter <= programs.size() * dataset.rows() / 500);
}

TEST_CASE("The GLSL and HLSL exports pass glslangValidator", "[gp]") {
  if (!tool_available("glslangValidator")) {
    SKIP("glslangValidator is not installed (Debian: glslang-tools); GLSL and HLSL exports not validated");
  }
  TempDir dir;
  ExportOptions options;
  options.input_names = {"x", "y"};
  options.language = ExportLanguage::glsl;
  const std::string glsl = "#version 450\n" + export_function(every_operator_program(), options) +
                           "layout(location = 0) in vec2 uv;\nlayout(location = 0) out vec4 color;\n"
                           "void main() { color = vec4(model(uv.x, uv.y)); }\n";
  write(dir.path / "model.frag", glsl);
  const std::string log = " > " + (dir.path / "log.txt").string() + " 2>&1";
  CHECK(std::system(("glslangValidator " + (dir.path / "model.frag").string() + log).c_str()) == 0);
  options.language = ExportLanguage::hlsl;
  const std::string hlsl = export_function(every_operator_program(), options) +
                           "float4 main(float2 uv : TEXCOORD0) : SV_Target { return model(uv.x, uv.y); }\n";
  write(dir.path / "model.hlsl", hlsl);
  const std::string spirv = " -o " + (dir.path / "model.spv").string();
  CHECK(std::system(
            ("glslangValidator -D -V -e main -S frag " + (dir.path / "model.hlsl").string() + spirv + log).c_str()) ==
        0);
}
