// docs/job-files.md against the job-file schemas: every key table names exactly the keys of its schema, each
// with the schema's type, default, choices and range. Every mismatch goes into one failure message, one line
// each: "SCHEMA 'KEY' WHAT: docs say ..., code says ... (docs/job-files.md:LINE)".
//
// Which table documents which schema. A key table is a table whose first column is "Key"; it documents the
// schema of the nearest heading above it:
//   "## Common keys"            the common keys (spec::common_schema(), path `job`);
//   "### Kind `K`"              the section of kind K (jobs::job_kinds(), path `K`);
//   a heading that is one `P`   the nested section or section list at path P of the common keys or of the
//                               kind above it (`evaluate.fit` is the section `fit` inside `evaluate`);
//   prose_headings below        headings that name their section in a sentence.
// Every schema reachable from the common schema and the kinds, nested ones included, needs exactly one table.
//
// The columns, per key (one key per row, written `key`):
//   Type            the word type_word() gives for the field's type (defined once, in the docs' table "How
//                   values are written");
//   Default         *required* for a required key; for a key with a default, that value as a literal
//                   (`0`, `1e-6`, `"01:00:00"`, `[128, 128]`, `[1, 2, π, 4]`, quotes optional for strings),
//                   compared as a value of the field's type; any other words for a key without a default;
//   Allowed values  for a choice (and a list of names restricted to some names): exactly the choices, each
//                   written `name`; for a bounded integer or number (of lists: their items): the bounds as
//                   "A to B", "≥ A" or "> A" (10⁹ and 2²⁰ count as numbers).
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "pbrfit/jobs/brdf/material_sets.hpp"
#include "pbrfit/jobs/job_kinds.hpp"
#include "pbrfit/jobs/sweep/problem_catalogue.hpp"
#include "pbrfit/spec/job_spec.hpp"

using namespace pbrfit;
using spec::Field;
using spec::FieldType;
using spec::Schema;

namespace {

const std::filesystem::path docs_file = std::filesystem::path(PBRFIT_SOURCE_DIR) / "docs" / "job-files.md";

// Headings that name the section they document in a sentence: the sections of sweep problems `expression`
// and `ltc` (the schemas of `sweep.expression` and `sweep.brdf`).
const std::map<std::string, std::string> prose_headings = {
    {"Models as expressions: problem `expression`", "sweep.expression"},
    {"LTC tables of any BRDF: problem `ltc`", "sweep.brdf"},
};

// ---- Reading the docs

struct Table {
  int line = 0;                  // of the header row
  std::string heading;           // the nearest heading above
  std::string root;              // `job` under "## Common keys", K under "### Kind `K`", else empty
  std::vector<std::string> header;  // lower case
  std::vector<std::vector<std::string>> rows;
  std::vector<int> row_lines;

  // The column whose header starts with `name`; -1 when there is none.
  int column(std::string_view name) const {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c].starts_with(name)) return int(c);
    return -1;
  }
  std::string where(std::size_t row) const { return "(docs/job-files.md:" + std::to_string(row_lines[row]) + ")"; }
};

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return std::string(s.substr(first, s.find_last_not_of(" \t") - first + 1));
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The cells of "| a | `b|c` | d |": a '|' inside backticks does not split.
std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool code = false;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '`') code = !code;
    if (line[i] == '|' && !code) {
      cells.push_back(trim(cell));
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  if (!trim(cell).empty()) cells.push_back(trim(cell));
  return cells;
}

// The texts written `like this` in s.
std::vector<std::string> code_spans(const std::string& s) {
  std::vector<std::string> spans;
  for (std::size_t open = s.find('`'); open != std::string::npos; open = s.find('`', open)) {
    const std::size_t close = s.find('`', open + 1);
    if (close == std::string::npos) break;
    spans.push_back(s.substr(open + 1, close - open - 1));
    open = close + 1;
  }
  return spans;
}

// The name of a cell that is exactly one `name`, else nullopt.
std::optional<std::string> single_span(const std::string& cell) {
  const auto spans = code_spans(cell);
  if (spans.size() == 1 && cell == "`" + spans[0] + "`") return spans[0];
  return std::nullopt;
}

// K of a heading "Kind `K`".
std::optional<std::string> kind_of_heading(const std::string& heading) {
  if (!heading.starts_with("Kind ")) return std::nullopt;
  return single_span(heading.substr(5));
}

std::vector<Table> read_tables() {
  std::ifstream in(docs_file);
  REQUIRE(in.good());
  std::vector<Table> tables;
  std::string line, heading, root;
  bool in_code = false, in_table = false;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.starts_with("```")) in_code = !in_code;
    if (in_code) continue;
    if (line.starts_with("#")) {
      const auto level = line.find_first_not_of('#');
      heading = trim(line.substr(level));
      if (level <= 2) root = heading == "Common keys" ? "job" : "";
      if (const auto kind = kind_of_heading(heading)) root = *kind;
    }
    if (!line.starts_with("|")) {
      in_table = false;
      continue;
    }
    if (!in_table) {
      in_table = true;
      Table t;
      t.line = number, t.heading = heading, t.root = root;
      for (const auto& cell : cells_of(line)) t.header.push_back(lower(cell));
      tables.push_back(std::move(t));
    } else if (line.find_first_not_of("|-: ") != std::string::npos) {  // not the |---| separator
      tables.back().rows.push_back(cells_of(line));
      tables.back().row_lines.push_back(number);
    }
  }
  return tables;
}

// The schema path a key table documents, or "" when its heading names none.
std::string schema_path(const Table& t) {
  if (const auto it = prose_headings.find(t.heading); it != prose_headings.end()) return it->second;
  if (t.heading == "Common keys") return "job";
  if (const auto kind = kind_of_heading(t.heading)) return *kind;
  if (const auto path = single_span(t.heading); path && !t.root.empty()) return t.root + "." + *path;
  return "";
}

// ---- The schemas

void collect(const Schema& schema, const std::string& path, std::map<std::string, const Schema*>& out) {
  out[path] = &schema;
  for (const Field& f : schema.fields())
    if (f.nested) collect(*f.nested, path + "." + f.name, out);
}

std::map<std::string, const Schema*> all_schemas() {
  std::map<std::string, const Schema*> schemas;
  collect(spec::common_schema(), "job", schemas);
  for (const auto& kind : jobs::job_kinds()) collect(kind.schema, kind.name, schemas);
  return schemas;
}

// The docs' word for a field's type; a list of a fixed count says it ("list of 2 integers").
std::string type_word(const Field& f) {
  const auto list = [&](const char* items) {
    return f.list_min == f.list_max ? "list of " + std::to_string(f.list_min) + " " + items
                                    : std::string("list of ") + items;
  };
  switch (f.type) {
    case FieldType::boolean: return "boolean";
    case FieldType::integer: return "integer";
    case FieldType::number: return "number";
    case FieldType::string: return "string";
    case FieldType::choice: return "choice";
    case FieldType::integer_list: return list("integers");
    case FieldType::number_list: return list("numbers");
    case FieldType::string_list: return list("names");
    case FieldType::section: return "mapping";
    case FieldType::section_list: return "list of mappings";
  }
  return "?";
}

// "list of 2 integers" -> "list of integers": the words of the table "How values are written".
std::string type_family(const std::string& word) {
  if (!word.starts_with("list of ")) return word;
  const auto space = word.find(' ', 8);
  const bool counted = space != std::string::npos && std::isdigit(static_cast<unsigned char>(word[8]));
  return counted ? "list of " + word.substr(space + 1) : word;
}

bool required(const Field& f) { return f.required || (f.type == FieldType::section_list && f.list_min > 0); }

// ---- Values

std::string number_text(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return std::string(text, end);
}

std::string scalar_text(const spec::Scalar& value) {
  const auto join = [](const auto& items, auto text) {
    std::string out = "[";
    for (std::size_t k = 0; k < items.size(); ++k) out += (k ? ", " : "") + text(items[k]);
    return out + "]";
  };
  return std::visit(
      [&](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
        else if constexpr (std::is_same_v<T, std::int64_t>) return std::to_string(v);
        else if constexpr (std::is_same_v<T, double>) return number_text(v);
        else if constexpr (std::is_same_v<T, std::string>) return "\"" + v + "\"";
        else if constexpr (std::is_same_v<T, std::vector<std::int64_t>>)
          return join(v, [](std::int64_t x) { return std::to_string(x); });
        else if constexpr (std::is_same_v<T, std::vector<double>>) return join(v, number_text);
        else return join(v, [](const std::string& x) { return x; });
      },
      value);
}

// A number written at s[at]: decimal (`-3`, `.5`, `1e-6`, with '+', '-' or '−' before it), `π`, or a power
// written with superscript digits (`10⁹`, `2²⁰`). Gives the value and the end, or nullopt.
std::optional<std::pair<double, std::size_t>> number_at(const std::string& s, std::size_t at) {
  static const std::string minus = "\u2212", pi = "\u03c0";
  static const std::vector<std::string> superscripts = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                                        "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  double sign = 1.0;
  std::size_t i = at;
  if (s.compare(i, minus.size(), minus) == 0) sign = -1.0, i += minus.size();
  else if (i < s.size() && (s[i] == '-' || s[i] == '+')) sign = s[i] == '-' ? -1.0 : 1.0, ++i;
  if (s.compare(i, pi.size(), pi) == 0) return std::pair{sign * std::numbers::pi, i + pi.size()};
  if (i >= s.size() || !(std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(s.data() + i, s.data() + s.size(), value);
  if (error != std::errc()) return std::nullopt;
  i = std::size_t(end - s.data());
  std::string exponent;
  for (bool more = true; more;) {
    more = false;
    for (std::size_t d = 0; d < superscripts.size(); ++d)
      if (s.compare(i, superscripts[d].size(), superscripts[d]) == 0) {
        exponent += char('0' + d), i += superscripts[d].size(), more = true;
        break;
      }
  }
  if (!exponent.empty()) value = std::pow(value, std::stod(exponent));
  return std::pair{sign * value, i};
}

std::optional<double> number_of(const std::string& text) {
  const auto n = number_at(text, 0);
  if (!n || n->second != text.size()) return std::nullopt;
  return n->first;
}

bool same_number(double a, double b) { return a == b || std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); }

std::string unquote(const std::string& text) {
  if (text.size() >= 2 && (text.front() == '"' || text.front() == '\'') && text.back() == text.front())
    return text.substr(1, text.size() - 2);
  return text;
}

// The items of "[a, b]"; nullopt when the text is not a list.
std::optional<std::vector<std::string>> list_items(const std::string& text) {
  if (text.size() < 2 || text.front() != '[' || text.back() != ']') return std::nullopt;
  std::vector<std::string> items;
  const std::string inner = trim(text.substr(1, text.size() - 2));
  if (inner.empty()) return items;
  std::stringstream in(inner);
  for (std::string item; std::getline(in, item, ',');) items.push_back(trim(item));
  return items;
}

double as_number(const spec::Scalar& v) {
  return std::holds_alternative<double>(v) ? std::get<double>(v) : double(std::get<std::int64_t>(v));
}

std::vector<double> as_numbers(const spec::Scalar& v) {
  if (std::holds_alternative<std::vector<double>>(v)) return std::get<std::vector<double>>(v);
  const auto& ints = std::get<std::vector<std::int64_t>>(v);
  return {ints.begin(), ints.end()};
}

// Whether the docs' default cell states the field's default value.
bool default_matches(const Field& f, const std::string& cell) {
  const spec::Scalar& v = *f.default_value;
  const auto span = single_span(cell);
  const std::string text = span ? *span : cell;
  switch (f.type) {
    case FieldType::boolean: return text == (std::get<bool>(v) ? "true" : "false");
    case FieldType::integer:
    case FieldType::number: {
      const auto n = number_of(text);
      return n && same_number(*n, as_number(v));
    }
    case FieldType::string:
    case FieldType::choice: return unquote(text) == std::get<std::string>(v);
    case FieldType::integer_list:
    case FieldType::number_list: {
      const auto items = list_items(text);
      const auto values = as_numbers(v);
      if (!items || items->size() != values.size()) return false;
      for (std::size_t k = 0; k < values.size(); ++k) {
        const auto n = number_of((*items)[k]);
        if (!n || !same_number(*n, values[k])) return false;
      }
      return true;
    }
    case FieldType::string_list: {
      const auto items = list_items(text);
      const auto& values = std::get<std::vector<std::string>>(v);
      if (!items || items->size() != values.size()) return false;
      for (std::size_t k = 0; k < values.size(); ++k)
        if (unquote((*items)[k]) != values[k]) return false;
      return true;
    }
    case FieldType::section:
    case FieldType::section_list: return false;  // sections take their defaults from their own keys
  }
  return false;
}

// Choice lists too long for a table cell, named in it instead: "one of the 100 MERL names" stands for exactly
// jobs::brdf::merl_material_names() (the cell must say how many there are).
struct NamedCatalogue {
  std::string words;
  const std::vector<std::string>& names;
};

std::vector<NamedCatalogue> named_catalogues() {
  return {{"MERL names", jobs::brdf::merl_material_names()}};
}

std::string listed(const std::set<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "(none)" : out;
}

// The bounds the allowed-values cell states: every "A to B", and every "≥ A" and "> A".
struct StatedBounds {
  std::vector<std::pair<double, double>> ranges;
  std::vector<double> at_least, above;
};

StatedBounds bounds_of(const std::string& cell) {
  StatedBounds out;
  struct Number { double value; std::size_t start, end; };
  std::vector<Number> numbers;
  for (std::size_t i = 0; i < cell.size();) {
    const bool starts_word = i == 0 || !(std::isalnum(static_cast<unsigned char>(cell[i - 1])) || cell[i - 1] == '_' ||
                                         cell[i - 1] == '.');
    const auto n = starts_word ? number_at(cell, i) : std::nullopt;
    if (n) {
      numbers.push_back({n->first, i, n->second});
      i = n->second;
    } else {
      ++i;
    }
  }
  for (std::size_t k = 0; k < numbers.size(); ++k) {
    const std::string before = trim(cell.substr(0, numbers[k].start));
    if (before.ends_with("\u2265")) out.at_least.push_back(numbers[k].value);
    if (before.ends_with(">")) out.above.push_back(numbers[k].value);
    if (k + 1 < numbers.size() && cell.substr(numbers[k].end, numbers[k + 1].start - numbers[k].end) == " to ")
      out.ranges.emplace_back(numbers[k].value, numbers[k + 1].value);
  }
  return out;
}

// "A to B", "≥ A" or "> A" as the schema states the field's bounds; "" when it has none. An upper bound at
// the largest 64-bit integer is no bound.
std::string bounds_text(const Field& f) {
  if (!f.min) return "";
  const bool bounded = f.max && *f.max < 9e18;
  if (bounded) return number_text(*f.min) + " to " + number_text(*f.max);
  return (f.min_exclusive ? "> " : "\u2265 ") + number_text(*f.min);
}

bool bounds_match(const Field& f, const std::string& cell) {
  const StatedBounds stated = bounds_of(cell);
  const auto has = [](const std::vector<double>& values, double v) {
    return std::ranges::any_of(values, [&](double x) { return same_number(x, v); });
  };
  if (f.max && *f.max < 9e18)
    return std::ranges::any_of(stated.ranges, [&](const auto& r) {
      return same_number(r.first, *f.min) && same_number(r.second, *f.max);
    });
  return has(f.min_exclusive ? stated.above : stated.at_least, *f.min);
}

// ---- The checks

struct Checker {
  std::vector<std::string> mismatches;

  void add(const std::string& what) { mismatches.push_back(what); }

  void check_key(const std::string& path, const Field& f, const Table& t, std::size_t row) {
    const auto& cells = t.rows[row];
    const std::string at = path + " '" + f.name + "' ";
    const auto cell = [&](const char* column) -> std::optional<std::string> {
      const int c = t.column(column);
      if (c < 0 || std::size_t(c) >= cells.size()) return std::nullopt;
      return cells[std::size_t(c)];
    };
    const auto type = cell("type"), fallback = cell("default"), allowed = cell("allowed values");
    if (!type || !fallback || !allowed) {
      add(at + "row: needs the columns Key, Type, Default and Allowed values " + t.where(row));
      return;
    }
    // 2. The type.
    if (*type != type_word(f)) add(at + "type: docs say '" + *type + "', code says '" + type_word(f) + "' " + t.where(row));
    // 3. The default.
    const bool docs_required = *fallback == "*required*";
    if (required(f)) {
      if (!docs_required) add(at + "default: docs say '" + *fallback + "', code says *required* " + t.where(row));
    } else if (f.default_value) {
      if (!default_matches(f, *fallback))
        add(at + "default: docs say '" + *fallback + "', code says " + scalar_text(*f.default_value) + " " + t.where(row));
    } else if (docs_required || fallback->empty()) {
      add(at + "default: docs say '" + *fallback + "', code says optional without a default (describe what " +
          "leaving it out does) " + t.where(row));
    }
    // 4. The choices.
    if (f.type == FieldType::choice || (f.type == FieldType::string_list && !f.choices.empty())) {
      const std::set<std::string> code(f.choices.begin(), f.choices.end());
      const auto spans = code_spans(*allowed);
      const std::set<std::string> docs(spans.begin(), spans.end());
      bool named = false;
      for (const auto& catalogue : named_catalogues())
        if (allowed->find(catalogue.words) != std::string::npos) {
          named = true;
          const std::string words = "the " + std::to_string(catalogue.names.size()) + " " + catalogue.words;
          if (code != std::set<std::string>(catalogue.names.begin(), catalogue.names.end()))
            add(at + "choices: docs say '" + *allowed + "', code has other choices: " + listed(code) + " " + t.where(row));
          else if (allowed->find(words) == std::string::npos)
            add(at + "choices: docs say '" + *allowed + "', code has " + words + " " + t.where(row));
        }
      if (!named && docs != code) {
        std::set<std::string> missing, extra;
        std::ranges::set_difference(code, docs, std::inserter(missing, missing.end()));
        std::ranges::set_difference(docs, code, std::inserter(extra, extra.end()));
        add(at + "choices: docs list " + listed(docs) + "; code has " + listed(code) + " (missing in docs: " +
            listed(missing) + "; not in code: " + listed(extra) + ") " + t.where(row));
      }
    }
    // 5. The bounds.
    if (f.min && !bounds_match(f, *allowed))
      add(at + "bounds: docs say '" + *allowed + "', code says " + bounds_text(f) + " " + t.where(row));
  }

  // 1. One row per key of the schema, no other rows; then the row's columns.
  void check_table(const std::string& path, const Schema& schema, const Table& t) {
    std::map<std::string, std::size_t> rows;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      const std::string& key_cell = t.rows[r].empty() ? std::string() : t.rows[r][0];
      // The common keys' table ends with the kind's section, `*<kind>*`: it is not a key of the common
      // schema but the section of each kind, checked against that kind's table.
      if (path == "job" && key_cell == "*`<kind>`*") continue;
      const auto key = single_span(key_cell);
      if (!key) {
        add(path + " row '" + key_cell + "': the Key column must hold one key, written `key` " + t.where(r));
      } else if (!schema.find(*key)) {
        add(path + " '" + *key + "': docs have a row, code has no such key " + t.where(r));
      } else if (!rows.emplace(*key, r).second) {
        add(path + " '" + *key + "': docs have two rows " + t.where(r));
      }
    }
    for (const Field& f : schema.fields()) {
      const auto found = rows.find(f.name);
      if (found == rows.end()) {
        add(path + " '" + f.name + "': docs have no row, code has the key (" + type_word(f) + ") (docs/job-files.md:" +
            std::to_string(t.line) + ")");
      } else {
        check_key(path, f, t, found->second);
      }
    }
  }

  std::string report() const {
    std::string out = std::to_string(mismatches.size()) + " mismatch(es) between docs/job-files.md and the code:";
    for (const auto& m : mismatches) out += "\n  " + m;
    return out;
  }
};

}  // namespace

TEST_CASE("docs/job-files.md documents every key of every job-file schema") {
  const auto tables = read_tables();
  const auto schemas = all_schemas();
  Checker check;

  std::map<std::string, const Table*> documented;
  for (const auto& t : tables) {
    if (t.header.empty() || t.header[0] != "key") continue;
    const std::string path = schema_path(t);
    const auto schema = schemas.find(path);
    if (schema == schemas.end()) {
      check.add("a key table under '" + t.heading + "' (docs/job-files.md:" + std::to_string(t.line) +
                ") documents no schema" + (path.empty() ? "" : " (code has no section " + path + ")"));
    } else if (!documented.emplace(path, &t).second) {
      check.add(path + ": docs have two key tables (docs/job-files.md:" + std::to_string(documented[path]->line) +
                " and " + std::to_string(t.line) + ")");
    } else {
      check.check_table(path, *schema->second, t);
    }
  }
  for (const auto& [path, schema] : schemas)
    if (!documented.contains(path))
      check.add(path + ": docs have no key table (a heading `" + path.substr(path.find('.') + 1) +
                "` under its kind, or its own kind heading)");

  // Every type word in use is explained in the table "How values are written".
  std::set<std::string> explained;
  for (const auto& t : tables)
    if (t.heading == "How values are written" && !t.header.empty() && t.header[0] == "type")
      for (const auto& row : t.rows) explained.insert(row.empty() ? "" : row[0]);
  for (const auto& [path, schema] : schemas)
    for (const Field& f : schema->fields())
      if (!explained.contains(type_family(type_word(f))))
        check.add("type '" + type_family(type_word(f)) + "' (of " + path + " '" + f.name +
                  "'): docs do not explain it in the table \"How values are written\"");

  INFO(check.report());
  CHECK(check.mismatches.empty());
}

// The sweep's problems table names every problem, and each problem's `objective` keys (the keys of
// sweep.objective, documented in their own table, which the problem reads: jobs::sweep::problem_catalogue()).
// Words written `like this` in the objective-keys column must be objective keys or values of its choices.
TEST_CASE("docs/job-files.md lists every sweep problem with the objective keys it reads") {
  const auto tables = read_tables();
  const auto problems_table = std::ranges::find_if(tables, [](const Table& t) {
    return t.root == "sweep" && !t.header.empty() && t.header[0] == "problem" && t.column("objective keys") >= 0;
  });
  REQUIRE(problems_table != tables.end());  // under "### Kind `sweep`": | problem | ... | objective keys ... |
  const Table& t = *problems_table;
  const int keys_column = t.column("objective keys");

  const Schema objective = jobs::sweep::objective_schema();
  std::set<std::string> values;  // the words of objective choices (`lobe`, `qmc`, ...)
  for (const Field& f : objective.fields()) values.insert(f.choices.begin(), f.choices.end());

  Checker check;
  std::set<std::string> documented;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto& cells = t.rows[r];
    const auto name = single_span(cells.empty() ? std::string() : cells[0]);
    if (!name) {
      check.add("sweep problems: row '" + (cells.empty() ? std::string() : cells[0]) + "' must name one problem " + t.where(r));
      continue;
    }
    documented.insert(*name);
    const auto entry = std::ranges::find_if(jobs::sweep::problem_catalogue(),
                                            [&](const auto& e) { return e.name == *name; });
    if (entry == jobs::sweep::problem_catalogue().end()) {
      check.add("sweep problem '" + *name + "': docs have a row, code has no such problem " + t.where(r));
      continue;
    }
    std::set<std::string> docs_keys;
    if (std::size_t(keys_column) < cells.size())
      for (const auto& span : code_spans(cells[std::size_t(keys_column)])) {
        if (objective.find(span)) docs_keys.insert(span);
        else if (!values.contains(span))
          check.add("sweep problem '" + *name + "': docs name `" + span + "`, neither a key of objective nor a " +
                    "value of one " + t.where(r));
      }
    const std::set<std::string> code_keys(entry->objective_keys.begin(), entry->objective_keys.end());
    if (docs_keys != code_keys)
      check.add("sweep problem '" + *name + "' objective keys: docs say " + listed(docs_keys) + "; code says " +
                listed(code_keys) + " " + t.where(r));
  }
  std::set<std::string> code_problems;
  for (const auto& e : jobs::sweep::problem_catalogue()) code_problems.insert(e.name);
  if (documented != code_problems)
    check.add("sweep problems: docs list " + listed(documented) + "; code has " + listed(code_problems));

  INFO(check.report());
  CHECK(check.mismatches.empty());
}
