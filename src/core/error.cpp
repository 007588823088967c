#include "pbrfit/core/error.hpp"

namespace pbrfit {

std::string format_error(const SourcePosition& where, const std::string& message) {
  std::string out = where.file;
  if (where.line > 0) {
    out.append(":").append(std::to_string(where.line));
    if (where.column > 0) out.append(":").append(std::to_string(where.column));
  }
  return out.append(": error: ").append(message);
}

InputError::InputError(SourcePosition where, const std::string& message)
    : std::runtime_error(format_error(where, message)), where_(std::move(where)), message_(message) {}

}  // namespace pbrfit
