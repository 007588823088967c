#include "pbrfit/jobs/symreg/result_table_source.hpp"

#include <cmath>
#include <numeric>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/result_file.hpp"

namespace pbrfit::jobs::symreg {

SymregOutput output_from_columns(const std::string& name, const std::vector<std::string>& inputs,
                                 const std::vector<std::vector<double>>& input_columns, const std::vector<double>& target) {
  std::vector<std::size_t> rows;
  for (std::size_t r = 0; r < target.size(); ++r) {
    bool finite = std::isfinite(target[r]);
    for (const auto& column : input_columns) finite = finite && std::isfinite(column[r]);
    if (finite) rows.push_back(r);
  }
  SymregOutput out{name, inputs, {}, {}};
  out.train.inputs.resize(Eigen::Index(rows.size()), Eigen::Index(inputs.size()));
  out.train.target.resize(Eigen::Index(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (std::size_t k = 0; k < inputs.size(); ++k) out.train.inputs(Eigen::Index(i), Eigen::Index(k)) = input_columns[k][rows[i]];
    out.train.target[Eigen::Index(i)] = target[rows[i]];
  }
  return out;
}

SymregOutput output_from_result_table(const std::string& path, const std::string& table) {
  const auto slash = table.rfind('/');
  if (slash == std::string::npos || slash == 0) throw RunError("a table is named GROUP/TABLE");
  const std::string group = table.substr(0, slash);
  std::vector<std::uint64_t> dims;
  const std::vector<double> values = store::read_table(path, table, &dims);
  const auto axes = store::read_name_list_attribute(path, table, "axes");
  if (axes.size() != dims.size()) throw RunError("it is not a table over its group's axes");
  std::vector<std::vector<double>> axis_values;
  for (std::size_t d = 0; d < axes.size(); ++d) {
    axis_values.push_back(store::read_table(path, group + "/" + axes[d]));
    if (axis_values.back().size() != dims[d]) throw RunError("its axis '" + axes[d] + "' does not match its shape");
  }
  std::vector<std::vector<double>> inputs(axes.size(), std::vector<double>(values.size()));
  for (std::size_t cell = 0; cell < values.size(); ++cell) {
    std::size_t rest = cell;
    for (std::size_t d = axes.size(); d-- > 0;) {
      inputs[d][cell] = axis_values[d][rest % dims[d]];
      rest /= dims[d];
    }
  }
  return output_from_columns(table.substr(slash + 1), axes, inputs, values);
}

}  // namespace pbrfit::jobs::symreg
