#pragma once
// The wording of validation messages: what a field requires, and user text quoted on one line.
#include <string>
#include <string_view>
#include <vector>

#include "pbrfit/core/quoted_text.hpp"
#include "pbrfit/spec/schema.hpp"

namespace pbrfit::spec {

using pbrfit::quote;  // core/quoted_text.hpp

// Shortest natural form: integral values as integers ("65536"), others as %g ("0.5", "1e-06").
std::string format_number(double value);

std::string join(const std::vector<std::string>& items, std::string_view separator = ", ");
// "one of a, b, c" for short lists; "one of 100 names (a, b, ..., z)" for long ones.
std::string choice_list(const std::vector<std::string>& choices);

// "an integer", "a number", "true or false", "a string", "one of a, b, c",
// "a list of 2 integers" / "a list of 1 to 3 integers", "a mapping".
std::string type_requirement(const Field& field);

// "between 1 and 65536", "greater than 0", "at least 0", "at most 9", ...; "" when unbounded.
std::string range_requirement(const Field& field);
bool in_range(const Field& field, double value);

// "; did you mean 'x'?" for the closest candidate, or "" when none is close.
std::string suggestion(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace pbrfit::spec
