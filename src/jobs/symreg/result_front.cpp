// Reads each field of <output>/front whole, through the store's record-field readers; the contract is
// in result_front.hpp.
#include "pbrfit/jobs/symreg/result_front.hpp"

#include <cmath>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/quoted_text.hpp"
#include "pbrfit/jobs/symreg/result_table_source.hpp"
#include "pbrfit/store/record_fields.hpp"
#include "pbrfit/store/result_file.hpp"

namespace pbrfit::jobs::symreg {

std::vector<std::string> result_outputs(const std::string& path) {
  auto names = store::read_group_names(path, "");
  std::erase(names, std::string("subexpressions"));
  return names;
}

std::optional<std::size_t> lowest_test_error_member(const OutputFront& front) {
  std::optional<std::size_t> best;
  for (std::size_t k = 0; k < front.members.size(); ++k)
    if (!std::isnan(front.members[k].test_rmse) && (!best || front.members[k].test_rmse < front.members[*best].test_rmse))
      best = k;
  return best;
}

OutputFront read_output_front(const std::string& path, const std::string& output) {
  OutputFront front{output, store::read_name_list_attribute(path, output, "inputs"), {}};
  const std::string table = output + "/front";
  const auto expressions = store::read_text_field(path, table, "expression");
  const auto costs = store::read_number_field(path, table, "cost");
  const auto rmse = store::read_number_field(path, table, "rmse");
  const auto max_abs = store::read_number_field(path, table, "max_abs_error");
  const auto test_rmse = store::read_number_field(path, table, "test_rmse");
  const auto knee = store::read_number_field(path, table, "knee");
  const std::size_t rows = expressions.size();
  if (costs.size() != rows || rmse.size() != rows || max_abs.size() != rows || test_rmse.size() != rows ||
      knee.size() != rows)
    throw RunError("the front of " + quote(output) + " changed while it was read (the job is writing it); try again");
  for (std::size_t k = 0; k < rows; ++k)
    front.members.push_back({expressions[k], costs[k], rmse[k], max_abs[k], test_rmse[k], knee[k] == 1.0});
  return front;
}

}  // namespace pbrfit::jobs::symreg
