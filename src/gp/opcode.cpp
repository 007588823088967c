#include "pbrfit/gp/opcode.hpp"

namespace pbrfit::gp {

std::optional<Opcode> opcode_named(std::string_view text) {
  for (std::size_t i = 0; i < opcode_count; ++i) {
    if (opcode_table[i].name == text) return static_cast<Opcode>(i);
  }
  return std::nullopt;
}

}  // namespace pbrfit::gp
