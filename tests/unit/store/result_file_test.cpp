#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/result_file.hpp"

using namespace pbrfit;

namespace {

std::string temporary_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "pbrfit-store-tests";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

store::ResultLayout grid_layout() {
  store::Group g;
  g.name = "grid";
  g.description = "test grid";
  g.attributes = {{"parametrization", "alpha = r^2"}};
  g.axes = {{"row", {0.0, 0.5, 1.0}, "rows"}, {"column", {10.0, 20.0}, "columns"}};
  g.tables = {{"value", {"row", "column"}, "a table"}, {"per_row", {"row"}, "one per row"}};
  return {{g}};
}

store::RunInfo info() { return {"test-job", "lut", "name: test-job\n", 5, 2, "2026-01-01T00:00:00Z", "slurm job 7, restart 1"}; }

}  // namespace

TEST_CASE("blocks land at their offsets; rows not yet written read as NaN; progress is readable") {
  const auto path = temporary_path("result.h5");
  store::ResultFile file(path, grid_layout(), info());
  file.add({{"grid", "value", {2, 0}, {1, 2}, {5.0, 6.0}}, {"grid", "per_row", {2}, {1}, {9.0}}});
  store::Progress p;
  p.items_done = 1;
  p.items_total = 3;
  p.headline = "one row";
  file.flush(p);

  std::vector<std::uint64_t> dims;
  const auto values = store::read_table(path, "grid/value", &dims);
  REQUIRE(dims == std::vector<std::uint64_t>{3, 2});
  CHECK(std::isnan(values[0]));
  CHECK(values[4] == 5.0);
  CHECK(values[5] == 6.0);

  const auto s = store::read_result_summary(path);
  CHECK(s.job_name == "test-job");
  CHECK(s.job_kind == "lut");
  CHECK(s.job_yaml == "name: test-job\n");
  CHECK(s.seed == 5);
  CHECK(s.ranks == 2);
  CHECK(s.state == "running");
  CHECK(s.items_done == 1);
  CHECK(s.items_total == 3);
  CHECK(s.headline == "one row");
  CHECK(s.scheduler_job == "slurm job 7, restart 1");

  file.add({{"grid", "value", {0, 0}, {2, 2}, {1, 2, 3, 4}}});
  p.state = "complete";
  p.items_done = 3;
  file.flush(p);
  CHECK(store::read_table(path, "grid/value") == std::vector<double>{1, 2, 3, 4, 5, 6});
  CHECK(store::read_result_summary(path).state == "complete");
  CHECK(store::read_table(path, "grid/row") == std::vector<double>{0.0, 0.5, 1.0});
}

TEST_CASE("a file that is not a pbrfit result is an input error") {
  const auto path = temporary_path("not-hdf5.h5");
  std::ofstream(path) << "plain text";
  REQUIRE_THROWS_WITH(store::read_result_summary(path),
                      Catch::Matchers::StartsWith(path + ": error: not a readable HDF5 file"));
  REQUIRE_THROWS_AS(store::read_result_summary(temporary_path("absent.h5")), InputError);
}
