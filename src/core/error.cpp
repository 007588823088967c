#include "pbrfit/core/error.hpp"

#include "pbrfit/core/quoted_text.hpp"

namespace pbrfit {

std::string format_error(const SourcePosition& where, const std::string& message) {
  std::string out = one_line(where.file);
  if (where.line > 0) {
    out.append(":").append(std::to_string(where.line));
    if (where.column > 0) out.append(":").append(std::to_string(where.column));
  }
  return out.append(": error: ").append(one_line(message));
}

InputError::InputError(SourcePosition where, const std::string& message)
    : std::runtime_error(format_error(where, message)), where_(std::move(where)), message_(message) {}

}  // namespace pbrfit
