#pragma once
// How integers and numbers must be written in a job file. Quoting does not change a scalar's type:
// "5" and 5 are both the integer 5.
#include <cstdint>
#include <optional>
#include <string_view>

namespace pbrfit::spec {

// Decimal digits with an optional sign: 10, -3, +7 (not 10.0, 1e3 or 0x10).
bool has_integer_syntax(std::string_view text);
// The value, or nullopt when the syntax is wrong or the value does not fit 64 bits.
std::optional<std::int64_t> parse_integer(std::string_view text);

// Finite decimal numbers: 3, -0.5, .5, 1e-6, 2.5E+3 (not .inf, .nan or 0x1p3).
std::optional<double> parse_number(std::string_view text);

}  // namespace pbrfit::spec
