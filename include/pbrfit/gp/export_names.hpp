#pragma once
// Names an exported function (export.hpp) and its parameters can have in every export language at once:
// ASCII letters, digits and '_', not starting with a digit or '_' (reserved at global scope in C++), no
// "__" (reserved in C++ and GLSL), no "gl_" prefix (GLSL), and none of the keywords, reserved words, types
// and built-in functions of C++, HLSL and GLSL that such a function could meet.
//
// Contract: is_portable_name(portable_name(text)) for every text; a portable name is returned unchanged.
#include <string>
#include <string_view>

namespace pbrfit::gp {

bool is_portable_name(std::string_view name);

// The closest portable name: other characters become '_', runs of '_' one, a leading '_' is dropped, a
// leading digit or "gl_" gets an "f" before it, a reserved word a trailing '_'; empty becomes "model".
std::string portable_name(std::string_view text);

}  // namespace pbrfit::gp
