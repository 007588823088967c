#pragma once
// A program as a function in HLSL, GLSL or C++, with its constants, ready to paste into a shader or a
// source file. One local per live instruction, in program order; identity instructions vanish.
//
// Contract:
//  - the function reproduces semantics.hpp exactly: |a| under sqrt, rsqrt, log and log2, pow as
//    exp2(b * log2(|a|)), NaN-propagating min, max and saturate in C++ (the shading languages use their
//    built-ins, which agree wherever the interpreter's output is finite);
//  - float exports hold every constant as the float the float32 interpreter uses (rounded to nearest),
//    printed with the fewest digits that read back to it and a float suffix where the language needs
//    one; a double C++ export prints the double. Negative literals are parenthesized;
//  - C++ arithmetic matches the interpreter bitwise when compiled without FMA contraction
//    (-ffp-contract=off; GCC contracts by default in its GNU modes on FMA targets); transcendentals
//    follow the C library, within a few ulps of the interpreter's vectorized ones;
//  - the C++ text starts with #include <cmath> and defines an inline function.
#include <string>
#include <vector>

#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

enum class ExportLanguage { hlsl, glsl, cpp };

struct ExportOptions {
  ExportLanguage language = ExportLanguage::hlsl;
  std::string function_name = "model";
  std::vector<std::string> input_names;  // the parameters of the function; missing ones are x<k>
  std::size_t input_count = 0;           // parameters in the signature: max(this, input_names, inputs read)
  bool cpp_double = false;               // C++ only: double instead of float
};

std::string export_function(const Program& program, const ExportOptions& options);

// The literal of `value` in a language: a float literal rounded to float, unless as_double (C++ only).
std::string number_literal(double value, ExportLanguage language, bool as_double = false);

}  // namespace pbrfit::gp
