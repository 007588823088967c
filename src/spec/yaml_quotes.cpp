#include "yaml_quotes.hpp"

#include <unordered_set>

#include "pbrfit/core/error.hpp"

namespace pbrfit::spec {

namespace {

// Whether the quoted scalar opening at `pos` closes before the end of its line.
bool closes_on_its_line(const std::string& text, std::size_t pos) {
  const char quote = text[pos];
  for (std::size_t i = pos + 1; i < text.size() && text[i] != '\n'; ++i) {
    if (quote == '"' && text[i] == '\\') {
      ++i;  // an escaped character, the quote included
    } else if (text[i] == quote) {
      if (quote == '\'' && i + 1 < text.size() && text[i + 1] == '\'') ++i;  // '' is a single quote inside
      else return true;
    }
  }
  return false;
}

void check_scalar(const YAML::Node& node, const YamlSource& source) {
  const auto pos = std::size_t(node.Mark().pos);
  const std::string& text = source.text();
  if (node.Mark().pos < 0 || pos >= text.size() || (text[pos] != '"' && text[pos] != '\'')) return;
  if (!closes_on_its_line(text, pos))
    throw InputError(source.position(node.Mark()),
                     std::string("unclosed quote: the value starting with ") + text[pos] +
                         " must end with " + text[pos] + " on the same line");
}

// Aliases make the tree a graph (possibly exponentially large when unfolded, possibly cyclic), so each
// collection is visited once, identified by where it starts in the text.
void check_nodes(const YAML::Node& node, const YamlSource& source, std::unordered_set<int>& visited) {
  if (!node.IsScalar() && !visited.insert(node.Mark().pos).second) return;
  if (node.IsScalar()) {
    check_scalar(node, source);
  } else if (node.IsMap()) {
    for (const auto& entry : node) {
      check_nodes(entry.first, source, visited);
      check_nodes(entry.second, source, visited);
    }
  } else if (node.IsSequence()) {
    for (const auto& item : node) check_nodes(item, source, visited);
  }
}

}  // namespace

void reject_unclosed_quotes(const YAML::Node& node, const YamlSource& source) {
  std::unordered_set<int> visited;
  check_nodes(node, source, visited);
}

}  // namespace pbrfit::spec
