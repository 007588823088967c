// pbrfit_expression_values: the reference values of the export tests. Parses each expression (the
// expression language, gp/expression_parser.hpp) over the named inputs and evaluates it with the tree
// walker (gp::walk_tree<double>, the engine's reference interpreter) on rows read from stdin.
//
//   pbrfit_expression_values INPUTS EXPRESSION...   (INPUTS: comma-separated names, in column order)
//
// Reads whitespace-separated numbers, one row of inputs after another; prints a line per row with each
// expression's value (%.17g, so the doubles read back exactly). Exit 2 with one line when an expression
// does not parse or the arguments are wrong.
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/tree_walker.hpp"

using namespace pbrfit;

namespace {

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> names;
  std::size_t start = 0;
  for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
    names.push_back(text.substr(start, comma - start));
  names.push_back(text.substr(start));
  return names;
}

bool parse_all(int argc, char** argv, const gp::ExpressionNames& names, std::vector<gp::Program>& programs) {
  for (int a = 2; a < argc; ++a) {
    const auto parsed = gp::parse_expression(argv[a], names);
    if (const auto* error = std::get_if<gp::ExpressionError>(&parsed)) {
      std::fprintf(stderr, "expression %d: %zu:%zu: %s\n", a - 1, error->line, error->column, error->message.c_str());
      return false;
    }
    programs.push_back(std::get<gp::ParsedExpression>(parsed).program);
  }
  return true;
}

bool read_row(std::vector<double>& row) {
  for (double& value : row)
    if (std::scanf("%lf", &value) != 1) return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: pbrfit_expression_values INPUTS EXPRESSION...\n");
    return 2;
  }
  const gp::ExpressionNames names{split_commas(argv[1]), {}};
  std::vector<gp::Program> programs;
  if (!parse_all(argc, argv, names, programs)) return 2;
  std::vector<double> row(names.inputs.size());
  while (read_row(row)) {
    for (std::size_t p = 0; p < programs.size(); ++p)
      std::printf("%s%.17g", p ? " " : "", gp::walk_tree<double>(programs[p], std::span<const double>(row)));
    std::printf("\n");
  }
  return 0;
}
