#include "pbrfit/gp/export.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <string_view>

#include "pbrfit/core/joined.hpp"
#include "pbrfit/gp/live_code.hpp"

namespace pbrfit::gp {
namespace {

template <class T>
std::string shortest(T value) {
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  std::string text(buffer.data(), result.ptr);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string infinite_literal(bool negative, ExportLanguage language, bool as_double) {
  const std::string_view sign = negative ? "-" : "";
  if (language == ExportLanguage::cpp) return joined({"(", sign, as_double ? "HUGE_VAL" : "HUGE_VALF", ")"});
  return joined({"(", sign, language == ExportLanguage::glsl ? "1.0 / 0.0" : "1.0f / 0.0f", ")"});
}

struct Emitter {
  const Program& program;
  const ExportOptions& options;
  std::vector<std::string> inputs;
  std::string type;
  std::string local_prefix = "t";  // locals are <prefix><instruction>, a prefix no input name starts with

  bool cpp() const { return options.language == ExportLanguage::cpp; }
  std::string literal(double value) const { return number_literal(value, options.language, options.cpp_double); }
  std::string operand(const Instruction& instruction, int j) const;
  std::string expression(const Instruction& instruction) const;
  std::string local(std::size_t i) const { return joined({local_prefix, std::to_string(i)}); }
  void choose_local_prefix();
};

void Emitter::choose_local_prefix() {
  const auto clashes = [&](const std::string& name) { return name.rfind(local_prefix, 0) == 0; };
  while (std::any_of(inputs.begin(), inputs.end(), clashes)) local_prefix = joined({"_", local_prefix});
}

std::string Emitter::operand(const Instruction& instruction, int j) const {
  Operand source = instruction.operands[j];
  double constant = instruction.constants[j];
  while (source.source == Source::instruction && program.code[source.index].op == Opcode::identity) {
    constant = program.code[source.index].constants[0];
    source = program.code[source.index].operands[0];
  }
  if (source.source == Source::input) return inputs[source.index];
  if (source.source == Source::constant) return literal(constant);
  return local(source.index);
}

std::string Emitter::expression(const Instruction& instruction) const {
  const std::string a = operand(instruction, 0);
  const std::string b = arity(instruction.op) > 1 ? operand(instruction, 1) : "";
  const std::string c = arity(instruction.op) > 2 ? operand(instruction, 2) : "";
  const std::string_view s = cpp() ? "std::" : "";
  const std::string abs_a = joined({s, "abs(", a, ")"});
  const bool glsl = options.language == ExportLanguage::glsl;
  switch (instruction.op) {
    case Opcode::identity:
      return a;
    case Opcode::add:
      return joined({a, " + ", b});
    case Opcode::sub:
      return joined({a, " - ", b});
    case Opcode::mul:
      return joined({a, " * ", b});
    case Opcode::div:
      return joined({a, " / ", b});
    case Opcode::fma:
      return options.language == ExportLanguage::hlsl ? joined({"mad(", a, ", ", b, ", ", c, ")"})
                                                      : joined({a, " * ", b, " + ", c});
    case Opcode::min:
      return cpp() ? joined({"(", a, " < ", b, " || ", a, " != ", a, ") ? ", a, " : ", b})
                   : joined({"min(", a, ", ", b, ")"});
    case Opcode::max:
      return cpp() ? joined({"(", a, " > ", b, " || ", a, " != ", a, ") ? ", a, " : ", b})
                   : joined({"max(", a, ", ", b, ")"});
    case Opcode::abs:
      return abs_a;
    case Opcode::neg:
      return joined({"-", a});
    case Opcode::sqrt:
      return joined({s, "sqrt(", abs_a, ")"});
    case Opcode::rsqrt:
      if (cpp()) return joined({literal(1.0), " / std::sqrt(", abs_a, ")"});
      return joined({glsl ? "inversesqrt(" : "rsqrt(", abs_a, ")"});
    case Opcode::exp:
      return joined({s, "exp(", a, ")"});
    case Opcode::exp2:
      return joined({s, "exp2(", a, ")"});
    case Opcode::log:
      return joined({s, "log(", abs_a, ")"});
    case Opcode::log2:
      return joined({s, "log2(", abs_a, ")"});
    case Opcode::pow:
      return joined({s, "exp2(", b, " * ", s, "log2(", abs_a, "))"});
    case Opcode::sin:
      return joined({s, "sin(", a, ")"});
    case Opcode::cos:
      return joined({s, "cos(", a, ")"});
    case Opcode::tan:
      return joined({s, "tan(", a, ")"});
    case Opcode::asin:
      return joined({s, "asin(", a, ")"});
    case Opcode::acos:
      return joined({s, "acos(", a, ")"});
    case Opcode::atan:
      return joined({s, "atan(", a, ")"});
    case Opcode::saturate: {
      const std::string zero = literal(0.0);
      const std::string one = literal(1.0);
      if (cpp()) return joined({a, " < ", zero, " ? ", zero, " : (", a, " > ", one, " ? ", one, " : ", a, ")"});
      return glsl ? joined({"clamp(", a, ", 0.0, 1.0)"}) : joined({"saturate(", a, ")"});
    }
  }
  return a;
}

std::size_t inputs_read(const Program& program) {
  std::size_t count = 0;
  for (const Instruction& instruction : program.instructions()) {
    for (int j = 0; j < arity(instruction.op); ++j) {
      if (instruction.operands[j].source == Source::input)
        count = std::max<std::size_t>(count, instruction.operands[j].index + 1u);
    }
  }
  return count;
}

}  // namespace

std::string number_literal(double value, ExportLanguage language, bool as_double) {
  const bool use_double = as_double && language == ExportLanguage::cpp;
  const double stored = use_double ? value : static_cast<double>(static_cast<float>(value));
  if (std::isinf(stored)) return infinite_literal(stored < 0.0, language, use_double);
  std::string text = use_double ? shortest(value) : shortest(static_cast<float>(value));
  if (!use_double && language != ExportLanguage::glsl) text += "f";
  return std::signbit(stored) ? joined({"(", text, ")"}) : text;
}

std::string export_function(const Program& program, const ExportOptions& options) {
  Emitter emitter{program, options, options.input_names, options.cpp_double ? "double" : "float"};
  const std::size_t parameters = std::max({options.input_count, options.input_names.size(), inputs_read(program)});
  for (std::size_t k = emitter.inputs.size(); k < parameters; ++k)
    emitter.inputs.push_back(joined({"x", std::to_string(k)}));
  emitter.choose_local_prefix();
  std::string text = emitter.cpp() ? "#include <cmath>\n\ninline " : "";
  text += joined({emitter.type, " ", options.function_name, "("});
  for (std::size_t k = 0; k < parameters; ++k)
    text += joined({k == 0 ? "" : ", ", emitter.type, " ", emitter.inputs[k]});
  text += ") {\n";
  const LiveMask live = live_instructions(program);
  for (std::size_t i = 0; i < program.length; ++i) {
    if (!live.test(i) || program.code[i].op == Opcode::identity) continue;
    text += joined({"  ", emitter.type, " ", emitter.local(i), " = ", emitter.expression(program.code[i]), ";\n"});
  }
  const std::string result = program.output().op == Opcode::identity ? emitter.operand(program.output(), 0)
                                                                     : emitter.local(program.length - 1u);
  return text + joined({"  return ", result, ";\n}\n"});
}

}  // namespace pbrfit::gp
