#pragma once
// User text inside one-line messages. Every message pbrfit prints is one line, whatever a job file, a
// path or an option holds: control characters are escaped (\n, \t, \x00, ...) and quoted values are
// shortened.
#include <string>
#include <string_view>

namespace pbrfit {

// 'text' in single quotes, control characters escaped, shortened to 60 characters with "...".
std::string quote(std::string_view text);

// text with control characters escaped, not shortened.
std::string one_line(std::string_view text);

// text with control characters escaped and, like quote(), shortened to 60 characters; no quotes (for
// numbers as written).
std::string shortened(std::string_view text);

// True if text holds a control character (NUL, newline, tab, DEL, ...).
bool has_control_character(std::string_view text);

}  // namespace pbrfit
