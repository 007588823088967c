#include "pbrfit/texture/texture.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>
#include <string_view>

#include "encoding.hpp"

namespace pbrfit::texture {
namespace {

constexpr std::size_t largest_size = (std::size_t(1) << 31) - 1;
constexpr std::size_t longest_name = 64;

[[noreturn]] void refuse(const Texture& t, const std::string& what) {
  throw std::invalid_argument("texture " + detail::quoted(t.name.substr(0, 80)) + ": " + what);
}

void check_level(const Texture& t, std::size_t level) {
  if (level >= t.levels)
    throw std::out_of_range("texture " + detail::quoted(t.name.substr(0, 80)) + " has " + std::to_string(t.levels) +
                            " mip levels, no level " + std::to_string(level));
}

std::size_t halved(std::size_t size, std::size_t level) {
  return level >= 64 ? 1 : std::max<std::size_t>(1, size >> level);
}

bool printable(char c, bool space_allowed) { return (c > ' ' && c < 0x7f) || (space_allowed && c == ' '); }

// a * b, or refuse when it does not fit a size_t.
std::size_t times(const Texture& t, std::size_t a, std::size_t b) {
  if (b != 0 && a > std::numeric_limits<std::size_t>::max() / b) refuse(t, "its sizes overflow the value count");
  return a * b;
}

std::size_t plus(const Texture& t, std::size_t a, std::size_t b) {
  if (a > std::numeric_limits<std::size_t>::max() - b) refuse(t, "its sizes overflow the value count");
  return a + b;
}

std::size_t full_chain(const Texture& t) {
  std::size_t largest = std::max({t.width, t.height, t.depth}), levels = 1;
  while (largest > 1) largest >>= 1, ++levels;
  return levels;
}

void check_sizes(const Texture& t) {
  const std::pair<const char*, std::size_t> sizes[] = {
      {"width", t.width}, {"height", t.height}, {"depth", t.depth}, {"layers", t.layers}, {"levels", t.levels}};
  for (const auto& [what, size] : sizes) {
    if (size == 0) refuse(t, std::string(what) + " is 0; it must be at least 1");
    if (size > largest_size) refuse(t, std::string(what) + " " + std::to_string(size) + " is not below 2^31");
  }
  if (t.depth > 1 && t.layers > 1)
    refuse(t, "a volume (depth " + std::to_string(t.depth) + ") cannot have array layers (" + std::to_string(t.layers) +
                  ")");
  if (t.levels > full_chain(t))
    refuse(t, std::to_string(t.levels) + " mip levels for " + std::to_string(t.width) + " x " +
                  std::to_string(t.height) + " x " + std::to_string(t.depth) + " texels; the full chain has " +
                  std::to_string(full_chain(t)));
}

void check_channels(const Texture& t) {
  if (t.channels.empty() || t.channels.size() > 4)
    refuse(t, std::to_string(t.channels.size()) + " channels; a texture has 1 to 4");
  std::set<std::string> seen;
  for (const std::string& c : t.channels) {
    const bool plain = !c.empty() && c.size() <= longest_name &&
                       std::all_of(c.begin(), c.end(), [](char ch) { return printable(ch, false) && ch != ','; });
    if (!plain)
      refuse(t, "channel name " + detail::quoted(c.substr(0, 80)) +
                    " is not 1 to 64 printable ASCII characters without spaces or commas");
    if (!seen.insert(c).second) refuse(t, "channel name \"" + c + "\" appears twice");
  }
}

void check_text(const Texture& t) {
  if (t.name.find('\0') != std::string::npos) refuse(t, "the name holds a NUL character");
  std::set<std::string> seen;
  for (const auto& [key, value] : t.metadata) {
    const bool plain = !key.empty() && key.size() <= longest_name &&
                       std::all_of(key.begin(), key.end(), [](char ch) { return printable(ch, false); });
    if (!plain)
      refuse(t, "metadata key " + detail::quoted(key.substr(0, 80)) +
                    " is not 1 to 64 printable ASCII characters without spaces");
    if (key == "name" || key == "channels" || std::string_view(key).starts_with("range:"))
      refuse(t, "metadata key \"" + key + "\" is reserved for the texture's own name, channels or ranges");
    if (!seen.insert(key).second) refuse(t, "metadata key \"" + key + "\" appears twice");
    if (value.find('\0') != std::string::npos) refuse(t, "metadata value of \"" + key + "\" holds a NUL character");
  }
}

}  // namespace

std::size_t level_width(const Texture& t, std::size_t level) {
  check_level(t, level);
  return halved(t.width, level);
}

std::size_t level_height(const Texture& t, std::size_t level) {
  check_level(t, level);
  return halved(t.height, level);
}

std::size_t level_depth(const Texture& t, std::size_t level) {
  check_level(t, level);
  return halved(t.depth, level);
}

std::size_t layer_value_count(const Texture& t, std::size_t level) {
  return times(t, times(t, times(t, level_width(t, level), level_height(t, level)), level_depth(t, level)),
               t.channels.size());
}

std::size_t level_offset(const Texture& t, std::size_t level, std::size_t layer) {
  if (level > t.levels || (level == t.levels && layer != 0)) check_level(t, level);
  if (layer >= t.layers && level < t.levels)
    throw std::out_of_range("texture " + detail::quoted(t.name.substr(0, 80)) + " has " + std::to_string(t.layers) +
                            " layers, no layer " + std::to_string(layer));
  std::size_t offset = 0;
  for (std::size_t k = 0; k < level; ++k) offset = plus(t, offset, times(t, layer_value_count(t, k), t.layers));
  if (level < t.levels) offset = plus(t, offset, times(t, layer_value_count(t, level), layer));
  return offset;
}

void validate(const Texture& t) {
  check_sizes(t);
  check_channels(t);
  check_text(t);
  const std::size_t count = level_offset(t, t.levels, 0);
  if (t.values.size() != count)
    refuse(t, "values holds " + std::to_string(t.values.size()) + " numbers; " + std::to_string(t.width) + " x " +
                  std::to_string(t.height) + " x " + std::to_string(t.depth) + " texels, " + std::to_string(t.layers) +
                  " layers, " + std::to_string(t.levels) + " levels and " + std::to_string(t.channels.size()) +
                  " channels need " + std::to_string(count));
}

}  // namespace pbrfit::texture
