#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pbrfit/spec/job_spec.hpp"

namespace pbrfit::spec {
namespace {

constexpr std::size_t max_leading_digits = 9;  // keeps every total far from overflowing

std::optional<std::int64_t> digits_value(std::string_view text, std::size_t max_digits) {
  if (text.empty() || text.size() > max_digits) return std::nullopt;
  std::int64_t value = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + (c - '0');
  }
  return value;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

// A field after the leading one: one or two digits, below limit.
std::optional<std::int64_t> trailing_field(std::string_view text, std::int64_t limit) {
  const auto value = digits_value(text, 2);
  if (!value || *value >= limit) return std::nullopt;
  return value;
}

// Units of the clock fields (after "D-", hours come first; without days, MM / MM:SS / HH:MM:SS).
std::optional<std::int64_t> clock_seconds(const std::vector<std::string_view>& fields,
                                          const std::vector<std::int64_t>& units,
                                          const std::vector<std::int64_t>& limits,
                                          std::size_t leading_digits) {
  const auto leading = digits_value(fields[0], leading_digits);
  if (!leading) return std::nullopt;
  if (limits[0] > 0 && *leading >= limits[0]) return std::nullopt;
  std::int64_t seconds = *leading * units[0];
  for (std::size_t i = 1; i < fields.size(); ++i) {
    const auto value = trailing_field(fields[i], limits[i]);
    if (!value) return std::nullopt;
    seconds += *value * units[i];
  }
  return seconds;
}

std::optional<std::int64_t> seconds_without_days(std::string_view text) {
  const std::vector<std::string_view> fields = split(text, ':');
  switch (fields.size()) {
    case 1: return clock_seconds(fields, {60}, {0}, max_leading_digits);
    case 2: return clock_seconds(fields, {60, 1}, {0, 60}, max_leading_digits);
    case 3: return clock_seconds(fields, {3600, 60, 1}, {0, 60, 60}, max_leading_digits);
    default: return std::nullopt;
  }
}

std::optional<std::int64_t> seconds_with_days(std::string_view days_text, std::string_view clock) {
  const auto days = digits_value(days_text, max_leading_digits);
  const std::vector<std::string_view> fields = split(clock, ':');
  if (!days || fields.size() > 3) return std::nullopt;
  const auto clock_part = clock_seconds(fields, {3600, 60, 1}, {24, 60, 60}, 2);
  if (!clock_part) return std::nullopt;
  return *days * 86400 + *clock_part;
}

}  // namespace

std::optional<std::int64_t> parse_slurm_time_limit(const std::string& text) {
  const std::size_t dash = text.find('-');
  if (dash == std::string::npos) return seconds_without_days(text);
  return seconds_with_days(std::string_view(text).substr(0, dash), std::string_view(text).substr(dash + 1));
}

}  // namespace pbrfit::spec
