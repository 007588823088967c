// The expression language (sweep models, BRDFs written in job files, reported programs): any text gives
// a program or an ExpressionError at a line and column inside the text, never an exception.
#include <cstdlib>
#include <variant>

#include "fuzz_support.hpp"
#include "pbrfit/gp/expression_parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pbrfit::gp::ExpressionNames names{{"x", "y", "nl", "nv", "nh", "vh", "roughness"}, {"a", "b"}};
  const auto text = pbrfit::fuzz::text_of(data, size);
  const auto parsed = pbrfit::gp::parse_expression(text, names);
  if (const auto* error = std::get_if<pbrfit::gp::ExpressionError>(&parsed)) {
    if (error->line < 1 || error->column < 1 || error->message.empty()) std::abort();
  }
  return 0;
}
