// The reserved words are those of C++20, HLSL (SM 6) and GLSL 4.60 (keywords and words reserved for
// future use) that are plain identifiers, with the types and built-in functions an exported function could
// collide with; the contract is in export_names.hpp.
#include "pbrfit/gp/export_names.hpp"

#include <algorithm>
#include <array>

namespace pbrfit::gp {
namespace {

constexpr std::array reserved_words = std::to_array<std::string_view>({
    // C++
    "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
    "char", "char8_t", "char16_t", "char32_t", "class", "co_await", "co_return", "co_yield", "compl", "concept",
    "const", "const_cast", "consteval", "constexpr", "constinit", "continue", "decltype", "default", "delete",
    "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for",
    "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
    "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast",
    "requires", "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "struct",
    "switch", "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename",
    "union", "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq", "std",
    "main",
    // GLSL
    "attribute", "uniform", "varying", "buffer", "shared", "coherent", "restrict", "readonly", "writeonly",
    "atomic_uint", "layout", "centroid", "flat", "smooth", "noperspective", "patch", "sample", "invariant",
    "precise", "subroutine", "in", "out", "inout", "discard", "lowp", "mediump", "highp", "precision",
    "common", "partition", "active", "filter", "resource", "input", "output", "external", "interface",
    "superp", "fixed", "half", "hvec2", "hvec3", "hvec4", "fvec2", "fvec3", "fvec4", "cast",
    "vec2", "vec3", "vec4", "dvec2", "dvec3", "dvec4", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3", "uvec4",
    "bvec2", "bvec3", "bvec4", "mat2", "mat3", "mat4", "uint", "texture",
    // HLSL
    "cbuffer", "tbuffer", "technique", "pass", "linear", "nointerpolation", "groupshared", "globallycoherent",
    "row_major", "column_major", "snorm", "unorm", "point", "line", "lineadj", "triangle", "triangleadj",
    "vector", "matrix", "string", "sampler", "dword", "min16float", "min10float", "min16int", "min12int",
    "min16uint", "float1", "float2", "float3", "float4", "half1", "half2", "half3", "half4", "int2", "int3",
    "int4", "uint2", "uint3", "uint4", "compile", "pixelfragment", "vertexfragment", "stateblock",
    "indices", "vertices", "primitives", "payload", "numthreads",
    // built-in functions of the exported code and its neighbours
    "abs", "min", "max", "clamp", "saturate", "sqrt", "rsqrt", "inversesqrt", "exp", "exp2", "log", "log2",
    "pow", "sin", "cos", "tan", "mad", "fma", "lerp", "mix", "step", "smoothstep", "frac", "fract", "floor",
    "ceil", "round", "dot", "cross", "length", "normalize", "sign", "isnan", "isinf",
});

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_reserved(std::string_view name) {
  return std::find(reserved_words.begin(), reserved_words.end(), name) != reserved_words.end();
}

// Letters, digits and single '_' only, no leading '_'.
std::string sanitized(std::string_view text) {
  std::string out;
  for (char c : text) {
    const char kept = is_letter(c) || is_digit(c) ? c : '_';
    if (kept == '_' && (out.empty() || out.back() == '_')) continue;
    out += kept;
  }
  return out;
}

}  // namespace

bool is_portable_name(std::string_view name) {
  if (name.empty() || !is_letter(name.front()) || name.find("__") != std::string_view::npos) return false;
  if (name.substr(0, 3) == "gl_" || is_reserved(name)) return false;
  return std::all_of(name.begin(), name.end(), [](char c) { return is_letter(c) || is_digit(c) || c == '_'; });
}

std::string portable_name(std::string_view text) {
  std::string name = sanitized(text);
  if (name.empty()) return "model";
  if (is_digit(name.front()) || name.substr(0, 3) == "gl_") name = std::string("f").append(name);
  if (is_reserved(name)) name += '_';
  return name;
}

}  // namespace pbrfit::gp
