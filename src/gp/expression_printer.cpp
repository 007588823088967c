#include "pbrfit/gp/expression_printer.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <map>
#include <string_view>

#include "pbrfit/core/joined.hpp"
#include "pbrfit/gp/live_code.hpp"

namespace pbrfit::gp {

std::string shortest_decimal(double value) {
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

namespace {

// Precedence of a printed piece: what it may appear inside without parentheses.
enum Level { additive = 1, multiplicative = 2, prefix = 3, atom = 4 };

struct Piece {
  std::string text;
  int level = atom;
  bool number = false;  // a non-negative numeric literal
};

std::string parenthesized(const Piece& piece, bool needed) {
  return needed ? joined({"(", piece.text, ")"}) : piece.text;
}

class Printer {
 public:
  Printer(const Program& program, const ExpressionNames& names, std::span<const std::vector<ConstantSlot>> slots);
  std::string print();

 private:
  // An operand with identity instructions followed through.
  std::pair<Operand, double> resolve(Operand operand, double constant) const;
  Piece operand(const Instruction& instruction, int j) const;
  Piece render(std::size_t i) const;
  void count_uses();
  std::string fresh_name();

  const Program& program_;
  const ExpressionNames& names_;
  std::map<std::pair<std::size_t, std::size_t>, std::string> parameter_at_;
  LiveMask live_;
  std::array<std::size_t, max_program_length> uses_{};
  std::array<std::string, max_program_length> bound_name_{};
  std::size_t names_made_ = 0;
};

Printer::Printer(const Program& program, const ExpressionNames& names, std::span<const std::vector<ConstantSlot>> slots)
    : program_(program), names_(names), live_(live_instructions(program)) {
  for (std::size_t k = 0; k < slots.size() && k < names.parameters.size(); ++k) {
    for (const ConstantSlot& slot : slots[k]) parameter_at_[{slot.instruction, slot.operand}] = names.parameters[k];
  }
}

std::pair<Operand, double> Printer::resolve(Operand operand, double constant) const {
  while (operand.source == Source::instruction && program_.code[operand.index].op == Opcode::identity) {
    const Instruction& forward = program_.code[operand.index];
    operand = forward.operands[0];
    constant = forward.constants[0];
  }
  return {operand, constant};
}

void Printer::count_uses() {
  for (std::size_t i = 0; i < program_.length; ++i) {
    const Instruction& instruction = program_.code[i];
    if (!live_.test(i) || instruction.op == Opcode::identity) continue;
    for (int j = 0; j < arity(instruction.op); ++j) {
      const auto [resolved, constant] = resolve(instruction.operands[j], instruction.constants[j]);
      if (resolved.source == Source::instruction) ++uses_[resolved.index];
    }
  }
}

std::string Printer::fresh_name() {
  for (;;) {
    const std::string candidate = joined({"t", std::to_string(++names_made_)});
    const auto taken = [&](const std::vector<std::string>& list) {
      return std::find(list.begin(), list.end(), candidate) != list.end();
    };
    if (!taken(names_.inputs) && !taken(names_.parameters)) return candidate;
  }
}

Piece Printer::operand(const Instruction& instruction, int j) const {
  const auto position = static_cast<std::size_t>(&instruction - program_.code.data());
  if (const auto named = parameter_at_.find({position, static_cast<std::size_t>(j)}); named != parameter_at_.end()) {
    return {named->second, atom, false};
  }
  const auto [resolved, constant] = resolve(instruction.operands[j], instruction.constants[j]);
  switch (resolved.source) {
    case Source::input:
      return {resolved.index < names_.inputs.size() ? names_.inputs[resolved.index]
                                                    : joined({"x", std::to_string(resolved.index)})};
    case Source::constant: {
      const bool negative = std::signbit(constant);
      return {shortest_decimal(constant), negative ? prefix : atom, !negative};
    }
    case Source::instruction:
      if (!bound_name_[resolved.index].empty()) return {bound_name_[resolved.index]};
      return render(resolved.index);
    case Source::none:
      break;
  }
  return {"0"};
}

Piece Printer::render(std::size_t i) const {
  const Instruction& instruction = program_.code[i];
  const Opcode op = instruction.op;
  if (op == Opcode::identity) return operand(instruction, 0);
  if (op == Opcode::neg) {
    const Piece inner = operand(instruction, 0);
    return {joined({"-", parenthesized(inner, inner.level < atom || inner.number)}), prefix};
  }
  if (op == Opcode::add || op == Opcode::sub || op == Opcode::mul || op == Opcode::div) {
    const int level = (op == Opcode::add || op == Opcode::sub) ? additive : multiplicative;
    const char* symbol = op == Opcode::add ? " + " : op == Opcode::sub ? " - " : op == Opcode::mul ? " * " : " / ";
    const Piece left = operand(instruction, 0);
    const Piece right = operand(instruction, 1);
    return {parenthesized(left, left.level < level) + symbol + parenthesized(right, right.level <= level), level};
  }
  std::string text(name(op));
  for (int j = 0; j < arity(op); ++j) text += joined({j == 0 ? "(" : ", ", operand(instruction, j).text});
  return {text + ")"};
}

std::string Printer::print() {
  count_uses();
  std::string text;
  for (std::size_t i = 0; i + 1 < program_.length; ++i) {
    if (!live_.test(i) || uses_[i] < 2 || program_.code[i].op == Opcode::identity) continue;
    const std::string bound = fresh_name();
    text += joined({bound, " = ", render(i).text, "\n"});
    bound_name_[i] = bound;
  }
  return text + render(program_.length - 1u).text;
}

}  // namespace

std::string print_expression(const Program& program, const ExpressionNames& names,
                             std::span<const std::vector<ConstantSlot>> parameter_slots) {
  return Printer(program, names, parameter_slots).print();
}

}  // namespace pbrfit::gp
