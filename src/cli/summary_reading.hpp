#pragma once
// Reading a result's summary from the command line, as `status` and `report` do: a read that lands
// while the writer replaces the file is retried (briefly); a result that cannot be read but has a
// checkpoint beside it is an InputError that says how to rebuild it. Other rejections are
// store::read_result_summary's InputErrors, naming the file.
#include <string>

#include "pbrfit/store/result_file.hpp"

namespace pbrfit::cli {

store::ResultSummary read_summary_or_explain(const std::string& path);

}  // namespace pbrfit::cli
