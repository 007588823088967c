// Tables as source code, each read by the tool that would consume it: the C++ header compiled by the
// system's compiler (the one building pbrfit) into a program that prints its values; the GLSL include through
// glslangValidator as GLSL ES 3.00 and, compiled to SPIR-V, as GLSL 4.50; the HLSL include compiled to SPIR-V
// by glslangValidator; the JavaScript module imported by node. SPIR-V's constants and the printed values are
// compared bitwise with the float cast (f32) or Imath's half (f16).
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <bit>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "pbrfit/texture/source_code.hpp"
#include "texture_test_support.hpp"

using namespace pbrfit;
using namespace pbrfit::texture;
using Catch::Matchers::ContainsSubstring;
using Catch::Matchers::Equals;

namespace {

std::string as_text(const Bytes& b) { return testing::text(b, 0, b.size()); }

Texture table() {
  Texture t = testing::sample(5, 3, 4, testing::Values::moderate, 1, 2, 2, 11);
  t.name = "ltc \"ggx\"\\";
  t.metadata = {{"source", "jobs/ltc-ggx.yaml\n*/ #endif \\"}, {"unit", "sr\u207b\u00b9"}};
  return t;
}

// The bits the consumer must see for values[i]: the float's, or for f16 the half's (cpp, js) or the float
// equal to the half (glsl, hlsl).
std::uint32_t expected(double v, Precision p, bool half_as_float) {
  if (p == Precision::f32) return testing::f32_bits(v);
  return half_as_float ? std::bit_cast<std::uint32_t>(testing::f16_value(v)) : testing::f16_bits(v);
}

std::size_t mismatches(const std::vector<std::uint32_t>& got, const Texture& t, Precision p, bool half_as_float) {
  if (got.size() != t.values.size()) return std::max(got.size(), t.values.size());
  std::size_t count = 0;
  for (std::size_t i = 0; i < got.size(); ++i) count += got[i] != expected(t.values[i], p, half_as_float);
  return count;
}

// The constituents of the one float-array OpConstantComposite with `count` elements, as bits.
std::vector<std::uint32_t> spirv_float_array(const std::filesystem::path& path, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint32_t> words;
  for (std::uint32_t w; in.read(reinterpret_cast<char*>(&w), 4);) words.push_back(w);
  REQUIRE(words.size() > 5);
  REQUIRE(words[0] == 0x07230203);                                        // SPIR-V magic
  std::map<std::uint32_t, std::uint32_t> float_types, arrays, constants;  // id -> width, element type, bits
  std::vector<std::uint32_t> found;
  std::size_t composites = 0;
  for (std::size_t at = 5; at < words.size();) {
    const std::uint32_t length = words[at] >> 16, opcode = words[at] & 0xffff;
    REQUIRE(length > 0);
    const std::uint32_t* op = &words[at];
    if (opcode == 22) float_types[op[1]] = op[2];                                                        // OpTypeFloat
    if (opcode == 28) arrays[op[1]] = op[2];                                                             // OpTypeArray
    if (opcode == 43 && float_types.count(op[1]) && float_types[op[1]] == 32) constants[op[2]] = op[3];  // OpConstant
    if (opcode == 44 && arrays.count(op[1]) && float_types.count(arrays[op[1]]) && length - 3 == count) {
      ++composites;  // OpConstantComposite of a float array
      found.clear();
      for (std::uint32_t k = 3; k < length; ++k)
        found.push_back(constants.count(op[k]) ? constants[op[k]] : 0xdeadbeef);
    }
    at += length;
  }
  CHECK(composites == 1);
  return found;
}

std::vector<std::uint32_t> numbers(std::istream& in, std::size_t count, int base = 10) {
  std::vector<std::uint32_t> out;
  std::string word;
  for (std::size_t k = 0; k < count && in >> word; ++k) out.push_back(std::uint32_t(std::stoul(word, nullptr, base)));
  return out;
}

}  // namespace

TEST_CASE("Source: the C++ header compiles (-Wall -Wextra -Wpedantic -Werror) and holds every value") {
  const Texture t = table();
  testing::write_file(testing::scratch("table_f32.hpp"), encode_source(t, Precision::f32, SourceLanguage::cpp, "TF_"));
  testing::write_file(testing::scratch("table_f16.hpp"), encode_source(t, Precision::f16, SourceLanguage::cpp, "TH_"));
  testing::write_file(testing::scratch("table_main.cpp"), std::string(R"(#include "table_f32.hpp"
#include "table_f16.hpp"
#include "table_f32.hpp"  // #pragma once
#include <cstdio>
#include <cstring>
static_assert(TF_WIDTH == 5 && TF_HEIGHT == 3 && TF_DEPTH == 1 && TF_LAYERS == 2 && TF_LEVELS == 2);
static_assert(TF_CHANNELS == 4 && TF_COUNT == (15 + 2) * 2 * 4 && TH_COUNT == TF_COUNT);
static_assert(TF_LEVEL_OFFSETS[0] == 0 && TF_LEVEL_OFFSETS[1] == 120 && TH_LEVEL_OFFSETS[1] == 120);
static_assert(sizeof(TF_DATA) == 4 * TF_COUNT && sizeof(TH_DATA) == 2 * TH_COUNT);
int main() {
  for (std::size_t i = 0; i < TF_COUNT; ++i) {
    std::uint32_t bits;
    std::memcpy(&bits, &TF_DATA[i], 4);
    std::printf("%08x\n", unsigned(bits));
  }
  for (std::size_t i = 0; i < TH_COUNT; ++i) std::printf("%04x\n", unsigned(TH_DATA[i]));
}
)"));
  const std::string program = testing::scratch("table_main").string();
  const auto compiled = testing::run(
      std::string(PBRFIT_CXX_COMPILER) + " -std=c++17 -Wall -Wextra -Wpedantic -Werror " +
      testing::shell_quoted(testing::scratch("table_main.cpp").string()) + " -o " + testing::shell_quoted(program));
  INFO(compiled.errors);
  REQUIRE(compiled.status == 0);
  const auto printed = testing::run(testing::shell_quoted(program));
  REQUIRE(printed.status == 0);
  std::istringstream out(printed.output);
  CHECK(mismatches(numbers(out, t.values.size(), 16), t, Precision::f32, false) == 0);
  CHECK(mismatches(numbers(out, t.values.size(), 16), t, Precision::f16, false) == 0);
}

TEST_CASE("Source: the GLSL include is valid GLSL ES 3.00 and GLSL 4.50, its SPIR-V constants every value") {
  if (!testing::tool_available("glslangValidator")) SKIP("glslangValidator is not installed (Debian: glslang-tools)");
  const Texture t = table();
  for (const Precision p : {Precision::f32, Precision::f16}) {
    const std::string include = as_text(encode_source(t, p, SourceLanguage::glsl, "LTC_"));
    const std::string use =
        "void main() { color = vec4(LTC_DATA[index + LTC_LEVEL_OFFSETS[1]]) + "
        "float(LTC_WIDTH * LTC_HEIGHT * LTC_DEPTH * LTC_LAYERS * LTC_LEVELS * LTC_CHANNELS); }\n";
    const auto es = testing::scratch("table_es.frag"), core = testing::scratch("table_450.frag");
    testing::write_file(es, "#version 300 es\nprecision mediump float;\n" + include +
                                "flat in highp int index;\nout vec4 color;\n" + use);
    testing::write_file(core, "#version 450\n" + include +
                                  "layout(location = 0) flat in int index;\nlayout(location = 0) out vec4 color;\n" +
                                  use);
    const auto es_run = testing::run("glslangValidator " + testing::shell_quoted(es.string()));
    INFO(es_run.output << es_run.errors);
    CHECK(es_run.status == 0);
    const auto spirv = testing::scratch("table_450.spv");
    const auto core_run = testing::run("glslangValidator -V " + testing::shell_quoted(core.string()) + " -o " +
                                       testing::shell_quoted(spirv.string()));
    INFO(core_run.output << core_run.errors);
    REQUIRE(core_run.status == 0);
    CHECK(mismatches(spirv_float_array(spirv, t.values.size()), t, p, true) == 0);
  }
}

TEST_CASE("Source: the HLSL include compiles to SPIR-V with every value") {
  if (!testing::tool_available("glslangValidator")) SKIP("glslangValidator is not installed (Debian: glslang-tools)");
  const Texture t = table();
  for (const Precision p : {Precision::f32, Precision::f16}) {
    const auto source = testing::scratch("table.hlsl"), spirv = testing::scratch("table_hlsl.spv");
    testing::write_file(source, as_text(encode_source(t, p, SourceLanguage::hlsl, "LTC_")) +
                                    "float4 main(nointerpolation int index : INDEX) : SV_Target {\n"
                                    "  return LTC_DATA[index + LTC_LEVEL_OFFSETS[1]] + LTC_COUNT * LTC_CHANNELS;\n}\n");
    const auto compiled =
        testing::run("glslangValidator -D -V -e main -S frag " + testing::shell_quoted(source.string()) + " -o " +
                     testing::shell_quoted(spirv.string()));
    INFO(compiled.output << compiled.errors);
    REQUIRE(compiled.status == 0);
    CHECK(mismatches(spirv_float_array(spirv, t.values.size()), t, p, true) == 0);
  }
}

TEST_CASE("Source: node imports the JavaScript modules, three.js's 64 x 64 RGBA layout included") {
  if (!testing::tool_available("node")) SKIP("node is not installed");
  const Texture t = table();
  Texture ltc = testing::sample(64, 64, 4, testing::Values::moderate, 1, 1, 1, 5);
  const std::vector<std::pair<std::string, Bytes>> modules = {
      {"f32", encode_source(t, Precision::f32, SourceLanguage::js, "LTC_")},
      {"f16", encode_source(t, Precision::f16, SourceLanguage::js, "LTC_")},
      {"ltc", encode_source(ltc, Precision::f16, SourceLanguage::js, "LTC_HALF_1_")}};
  std::string script;
  for (const auto& [name, bytes] : modules) {
    const auto path = testing::scratch("table_" + name + ".mjs");
    testing::write_file(path, bytes);
    script += "import * as " + name + " from '" + path.string() + "';\n";
  }
  script += R"(const show = (m, p) => {
  console.log([m[p + 'WIDTH'], m[p + 'HEIGHT'], m[p + 'DEPTH'], m[p + 'LAYERS'], m[p + 'LEVELS'], m[p + 'CHANNELS'],
               m[p + 'COUNT'], m[p + 'DATA'].constructor.name, m[p + 'LEVEL_OFFSETS'].join(',')].join(' '));
  const d = m[p + 'DATA'];
  console.log(Array.from(d instanceof Float32Array ? new Uint32Array(d.buffer) : d).join(' '));
};
show(f32, 'LTC_'); show(f16, 'LTC_'); show(ltc, 'LTC_HALF_1_');
)";
  testing::write_file(testing::scratch("table_show.mjs"), script);
  const auto result = testing::run("node " + testing::shell_quoted(testing::scratch("table_show.mjs").string()));
  INFO(result.errors);
  REQUIRE(result.status == 0);
  std::istringstream out(result.output);
  std::string line;
  REQUIRE(std::getline(out, line));
  CHECK(line == "5 3 1 2 2 4 136 Float32Array 0,120");
  REQUIRE(std::getline(out, line));
  std::istringstream f32(line);
  CHECK(mismatches(numbers(f32, t.values.size()), t, Precision::f32, false) == 0);
  REQUIRE(std::getline(out, line));
  CHECK(line == "5 3 1 2 2 4 136 Uint16Array 0,120");
  REQUIRE(std::getline(out, line));
  std::istringstream f16(line);
  CHECK(mismatches(numbers(f16, t.values.size()), t, Precision::f16, false) == 0);
  REQUIRE(std::getline(out, line));
  CHECK(line == "64 64 1 1 1 4 16384 Uint16Array 0");
  REQUIRE(std::getline(out, line));
  std::istringstream halves(line);
  CHECK(mismatches(numbers(halves, ltc.values.size()), ltc, Precision::f16, false) == 0);
}

TEST_CASE("Source: comments quote the name and metadata; float literals have 9 digits") {
  Texture t;
  t.name = "one";
  t.width = 3;
  t.channels = {"v"};
  t.values = {1.0, 0.1, -0.0};
  t.metadata = {{"k", "a\nb\\"}};
  const std::string cpp = as_text(encode_source(t, Precision::f32, SourceLanguage::cpp, "T_"));
  CHECK_THAT(cpp, ContainsSubstring("// \"one\": a table written by pbrfit\n"));
  CHECK_THAT(cpp, ContainsSubstring("// k: \"a\\nb\\\\\"\n"));
  CHECK_THAT(cpp, ContainsSubstring("inline constexpr float T_DATA[T_COUNT] = {\n  1.0f, 0.100000001f, -0.0f\n};\n"));
  CHECK(cpp.rfind("#pragma once\n", 0) == 0);
  CHECK_THAT(as_text(encode_source(t, Precision::f32, SourceLanguage::glsl, "T_")),
             ContainsSubstring("const highp float T_DATA[T_COUNT] = float[T_COUNT](\n  1.0, 0.100000001, -0.0\n);\n"));
  CHECK_THAT(as_text(encode_source(t, Precision::f16, SourceLanguage::hlsl, "T_")),
             ContainsSubstring("static const float T_DATA[T_COUNT] = {\n  1.0, 0.0999755859, -0.0\n};\n"));
  CHECK_THAT(as_text(encode_source(t, Precision::f16, SourceLanguage::js, "T_")),
             ContainsSubstring("export const T_DATA = new Uint16Array([\n  15360, 11878, 32768\n]);\n"));
  CHECK_THAT(as_text(encode_source(t, Precision::f16, SourceLanguage::cpp, "T_")),
             ContainsSubstring("inline constexpr std::uint16_t T_DATA[T_COUNT] = {\n  0x3c00, 0x2e66, 0x8000\n};\n"));
}

TEST_CASE("Source: refusals: prefixes that are no identifier start, values that are not finite") {
  const Texture t = testing::sample(2, 2, 1, testing::Values::moderate);
  for (const char* prefix : {"", "1A", "_A", "A-B", "A__B", "gl_X", "GL_X", "ä"}) {
    CAPTURE(prefix);
    CHECK_THROWS_WITH(encode_source(t, Precision::f32, SourceLanguage::glsl, prefix),
                      Catch::Matchers::StartsWith("glsl: prefix \"") && ContainsSubstring("is not a valid identifier"));
  }
  CHECK_THROWS_WITH(
      encode_source(t, Precision::f32, SourceLanguage::cpp, "1A"),
      Equals("cpp: prefix \"1A\" is not a valid identifier prefix: it starts with a digit or an underscore"));
  CHECK_NOTHROW(encode_source(t, Precision::f32, SourceLanguage::cpp, "a1_"));
  Texture big = t;
  big.values[3] = 70000.0;
  CHECK_NOTHROW(encode_source(big, Precision::f32, SourceLanguage::js, "T_"));
  CHECK_THROWS_WITH(encode_source(big, Precision::f16, SourceLanguage::js, "T_"),
                    Equals("js: value 70000 at level 0, texel (1, 1), channel R is not finite in f16"));
  big.values[3] = NAN;
  CHECK_THROWS_WITH(encode_source(big, Precision::f32, SourceLanguage::hlsl, "T_"),
                    Equals("hlsl: value nan at level 0, texel (1, 1), channel R is not finite"));
}
