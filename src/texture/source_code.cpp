#include "pbrfit/texture/source_code.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "encoding.hpp"

namespace pbrfit::texture {
namespace {

using namespace detail;

constexpr std::size_t per_line = 8, halves_per_line = 12;

const char* language_name(SourceLanguage language) {
  switch (language) {
    case SourceLanguage::cpp: return "cpp";
    case SourceLanguage::glsl: return "glsl";
    case SourceLanguage::hlsl: return "hlsl";
    case SourceLanguage::js: return "js";
  }
  return "source";
}

void check_prefix(const std::string& prefix, const char* language) {
  const auto why = [&]() -> std::string {
    if (prefix.empty()) return "is empty";
    if (std::isdigit(static_cast<unsigned char>(prefix[0])) || prefix[0] == '_')
      return "starts with a digit or an underscore";
    for (const char c : prefix)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
        return "holds characters other than A-Z, a-z, 0-9, _";
    if (prefix.find("__") != std::string::npos) return "holds \"__\" (reserved in C++ and GLSL)";
    if (prefix.size() >= 3 && std::tolower(static_cast<unsigned char>(prefix[0])) == 'g' &&
        std::tolower(static_cast<unsigned char>(prefix[1])) == 'l' && prefix[2] == '_')
      return "starts with \"gl_\" (reserved in GLSL)";
    return "";
  }();
  if (!why.empty()) refuse(language, "prefix " + quoted(prefix) + " is not a valid identifier prefix: it " + why);
}

// Float literal with 9 significant digits, always with a point or an exponent (GLSL and C++ need one).
std::string float_literal(float v, const char* suffix) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", double(v));
  std::string out = text;
  if (out.find_first_of(".e") == std::string::npos) out += ".0";
  return out + suffix;
}

std::string js_number(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", double(v));
  return text;
}

std::string hex16(std::uint16_t bits) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%04x", unsigned(bits));
  return text;
}

struct Writer {
  const Texture& t;
  Precision precision;
  SourceLanguage language;
  std::string p;  // the prefix
  std::string out;

  void line(const std::string& text) { out += text + "\n"; }

  void comments() {
    const std::string sizes = std::to_string(t.width) + " x " + std::to_string(t.height) +
                              (t.depth > 1 ? " x " + std::to_string(t.depth) : "") + " texels" +
                              (t.layers > 1 ? ", " + std::to_string(t.layers) + " array layers" : "") + ", " +
                              std::to_string(t.levels) + (t.levels == 1 ? " mip level" : " mip levels");
    line("// " + quoted(t.name) + ": a table written by pbrfit");
    line("// " + sizes + ", " + std::to_string(t.channels.size()) + " channels, " +
         (precision == Precision::f32 ? "32-bit floats" : "16-bit half floats") + ".");
    for (const auto& [key, value] : text_entries(t))
      if (key != "name") line("// " + key + ": " + quoted(value));
    line("// " + p + "DATA[" + p + "LEVEL_OFFSETS[l] + (((layer * d + z) * h + y) * w + x) * " + p +
         "CHANNELS + c] is");
    line("// channel c of texel (x, y, z) of layer `layer` in mip level l, where w = max(1, " + p +
         "WIDTH >> l), h and d alike.");
    if (precision == Precision::f16 && (language == SourceLanguage::glsl || language == SourceLanguage::hlsl))
      line("// Half precision: the values are rounded to half floats, written as the floats equal to them.");
    if (precision == Precision::f16 && language != SourceLanguage::glsl && language != SourceLanguage::hlsl)
      line("// Half precision: " + p + "DATA holds the IEEE 754 binary16 bits of each value.");
  }

  std::vector<std::pair<std::string, std::size_t>> sizes() const {
    return {{"WIDTH", t.width},        {"HEIGHT", t.height}, {"DEPTH", t.depth},
            {"LAYERS", t.layers},      {"LEVELS", t.levels}, {"CHANNELS", t.channels.size()},
            {"COUNT", t.values.size()}};
  }

  std::string offsets() const {
    std::string list;
    for (std::size_t level = 0; level < t.levels; ++level)
      list += (level ? ", " : "") + std::to_string(level_offset(t, level, 0));
    return list;
  }

  std::string value(std::size_t i) const {
    const double v = t.values[i];
    switch (language) {
      case SourceLanguage::cpp:
        return precision == Precision::f32 ? float_literal(to_float(v), "f") : hex16(half_bits(v));
      case SourceLanguage::glsl:
      case SourceLanguage::hlsl: return float_literal(precision == Precision::f32 ? to_float(v) : half_rounded(v), "");
      case SourceLanguage::js:
        return precision == Precision::f32 ? js_number(to_float(v)) : std::to_string(half_bits(v));
    }
    return "";
  }

  void values() {
    const std::size_t n =
        precision == Precision::f16 && (language == SourceLanguage::cpp || language == SourceLanguage::js)
            ? halves_per_line
            : per_line;
    for (std::size_t i = 0; i < t.values.size(); i += n) {
      std::string text = "  ";
      for (std::size_t k = i; k < std::min(i + n, t.values.size()); ++k) {
        text += value(k);
        if (k + 1 < t.values.size()) text += k + 1 < i + n ? ", " : ",";
      }
      line(text);
    }
  }

  void cpp() {
    line("#pragma once");
    comments();
    line("#include <cstddef>");
    line("#include <cstdint>");
    line("");
    for (const auto& [name, size] : sizes())
      line("inline constexpr std::size_t " + p + name + " = " + std::to_string(size) + ";");
    line("inline constexpr std::size_t " + p + "LEVEL_OFFSETS[" + p + "LEVELS] = {" + offsets() + "};");
    line(std::string("inline constexpr ") + (precision == Precision::f32 ? "float " : "std::uint16_t ") + p + "DATA[" +
         p + "COUNT] = {");
    values();
    line("};");
  }

  void glsl() {
    comments();
    for (const auto& [name, size] : sizes()) line("#define " + p + name + " " + std::to_string(size));
    line("const highp int " + p + "LEVEL_OFFSETS[" + p + "LEVELS] = int[" + p + "LEVELS](" + offsets() + ");");
    line("const highp float " + p + "DATA[" + p + "COUNT] = float[" + p + "COUNT](");
    values();
    line(");");
  }

  void hlsl() {
    comments();
    for (const auto& [name, size] : sizes()) line("#define " + p + name + " " + std::to_string(size));
    line("static const int " + p + "LEVEL_OFFSETS[" + p + "LEVELS] = {" + offsets() + "};");
    line("static const float " + p + "DATA[" + p + "COUNT] = {");
    values();
    line("};");
  }

  void js() {
    comments();
    for (const auto& [name, size] : sizes()) line("export const " + p + name + " = " + std::to_string(size) + ";");
    line("export const " + p + "LEVEL_OFFSETS = [" + offsets() + "];");
    line("export const " + p + "DATA = new " + (precision == Precision::f32 ? "Float32Array" : "Uint16Array") + "([");
    values();
    line("]);");
  }
};

}  // namespace

Bytes encode_source(const Texture& t, Precision precision, SourceLanguage language, const std::string& prefix) {
  const char* name = language_name(language);
  check_texture(t, name);
  check_prefix(prefix, name);
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    const float v = precision == Precision::f32 ? to_float(t.values[i]) : half_rounded(t.values[i]);
    if (!std::isfinite(v))
      refuse(name,
             "value " + number(t.values[i]) + " at " + texel_of(t, i) + " is not finite" +
                 (std::isfinite(t.values[i]) ? " in " + std::string(precision == Precision::f32 ? "f32" : "f16") : ""));
  }
  Writer writer{t, precision, language, prefix, {}};
  switch (language) {
    case SourceLanguage::cpp: writer.cpp(); break;
    case SourceLanguage::glsl: writer.glsl(); break;
    case SourceLanguage::hlsl: writer.hlsl(); break;
    case SourceLanguage::js: writer.js(); break;
  }
  return as_bytes(writer.out);
}

}  // namespace pbrfit::texture
