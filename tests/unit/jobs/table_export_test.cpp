// `pbrfit export`'s table side on a damaged result file: a file whose summary reads but one of whose tables
// does not (the result_file fuzz target's finding, tests/fuzz/regressions/result_file/) is refused with an
// InputError naming the file, as a file that does not open at all is, never a RunError of HDF5's.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <string>

#include "pbrfit/core/error.hpp"
#include "pbrfit/jobs/table_export.hpp"
#include "pbrfit/store/result_file.hpp"

using namespace pbrfit;

TEST_CASE("a result file with an unreadable table is refused as the user's damaged input") {
  const std::string path = PBRFIT_SOURCE_DIR "/tests/fuzz/regressions/result_file/lut-table-unreadable.h5";
  const auto summary = store::read_result_summary(path);
  REQUIRE(summary.job_kind == "lut");
  REQUIRE(summary.state == store::RunStatus::complete);
  const auto tables = jobs::exportable_tables(path, summary);
  REQUIRE(tables == std::vector<std::string>{"dfg"});
  jobs::TableRequest request;
  request.table = tables.front();
  try {
    (void)jobs::table_texture(path, summary, request);
    FAIL("the damaged table was exported");
  } catch (const InputError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Matchers::StartsWith(path + ": error: is damaged: HDF5: cannot read dfg/"));
  }
}
