#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <hdf5.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <filesystem>
#include <fstream>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/result_file.hpp"
#include "store_test_paths.hpp"

using namespace pbrfit;
using store::ValueType;

namespace {

store::ResultLayout grid_layout() {
  store::Group g;
  g.name = "grid";
  g.description = "test grid";
  g.attributes = {{"parametrization", "alpha = r^2"}};
  g.axes = {{"row", {0.0, 0.5, 1.0}, "rows"}, {"column", {10.0, 20.0}, "columns"}};
  g.tables = {{"value", {"row", "column"}, "a table"}, {"per_row", {"row"}, "one per row"}};
  return {{g}};
}

store::RunInfo info() {
  return {"test-job", "lut", "name: test-job\n", 5, 2, 3, "2026-01-01T00:00:00Z", "slurm job 7, restart 1"};
}

store::Progress progress(std::uint64_t done, store::RunStatus state = store::RunStatus::running) {
  store::Progress p;
  p.state = state;
  p.items_done = done;
  p.items_total = 3;
  p.headline = "one row";
  return p;
}

// Every kind of table the store offers, in one group.
store::ResultLayout typed_layout() {
  store::Group g;
  g.name = "typed";
  g.axes = {{"x", {0, 1, 2, 3}, "x"}, {"y", {0, 1, 2}, "y"}};
  g.tables = {
      {"single", {"x", "y"}, "float32", ValueType::f32},
      {"counts", {"x"}, "int32", ValueType::i32},
      {"flags", {"x"}, "uint8", ValueType::u8},
      {"names", {"x"}, "texts", ValueType::text},
      {"members", {"member"}, "records", ValueType::f64,
       {{"expression", ValueType::text, "its text"}, {"cost", ValueType::u32, "ops"}, {"error", ValueType::f64, "rmse"}},
       true},
      {"log", {"generation", "y"}, "growing numbers", ValueType::f64, {}, true, {2, 3}},
  };
  return {{g}};
}

}  // namespace

TEST_CASE("blocks land at their offsets; rows not yet written read as NaN; progress is readable") {
  const auto path = temporary_path("result.h5");
  store::ResultFile file(path, grid_layout(), info());
  file.write({{"grid", "value", {2, 0}, {1, 2}, {5.0, 6.0}, {}}, {"grid", "per_row", {2}, {1}, {9.0}, {}}}, progress(1));
  file.publish();

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
  CHECK(s.threads == 3);
  CHECK(s.state == store::RunStatus::running);
  CHECK(s.items_done == 1);
  CHECK(s.items_total == 3);
  CHECK(s.headline == "one row");
  CHECK(s.scheduler_job == "slurm job 7, restart 1");

  file.write({{"grid", "value", {0, 0}, {2, 2}, {1, 2, 3, 4}, {}}}, progress(3, store::RunStatus::complete));
  file.publish();
  CHECK(store::read_table(path, "grid/value") == std::vector<double>{1, 2, 3, 4, 5, 6});
  CHECK(store::read_result_summary(path).state == store::RunStatus::complete);
  CHECK(store::read_table(path, "grid/row") == std::vector<double>{0.0, 0.5, 1.0});
}

TEST_CASE("a table written cell by cell, out of order, in one batch holds every value in its place") {
  const auto path = temporary_path("cells.h5");
  store::ResultFile file(path, grid_layout(), info());
  std::vector<store::Block> cells;
  for (std::uint64_t i : {5, 0, 3, 1, 4, 2}) cells.push_back({"grid", "value", {i / 2, i % 2}, {1, 1}, {double(i)}, {}});
  file.write(cells, progress(3));
  file.publish();
  CHECK(store::read_table(path, "grid/value") == std::vector<double>{0, 1, 2, 3, 4, 5});
}

TEST_CASE("of two blocks for the same cells in one batch the later wins, whatever the order and the tables between") {
  const auto path = temporary_path("overwrite.h5");
  store::ResultFile file(path, grid_layout(), info());
  const std::vector<store::Block> blocks = {
      {"grid", "value", {0, 0}, {1, 1}, {1.0}, {}},      {"grid", "per_row", {0}, {1}, {7.0}, {}},
      {"grid", "value", {0, 1}, {1, 1}, {2.0}, {}},      {"grid", "value", {2, 1}, {1, 1}, {6.0}, {}},
      {"grid", "value", {0, 0}, {1, 1}, {9.0}, {}},      {"grid", "value", {1, 0}, {1, 2}, {3.0, 4.0}, {}},
      {"grid", "per_row", {1}, {2}, {8.0, 10.0}, {}},    {"grid", "value", {2, 0}, {1, 1}, {5.0}, {}},
      {"grid", "value", {1, 1}, {1, 1}, {-4.0}, {}},     {"grid", "per_row", {2}, {1}, {9.0}, {}},
  };
  file.write(blocks, progress(3));
  file.publish();
  CHECK(store::read_table(path, "grid/value") == std::vector<double>{9, 2, 3, -4, 5, 6});
  CHECK(store::read_table(path, "grid/per_row") == std::vector<double>{7, 8, 9});
}

TEST_CASE("tables keep their declared types: float32, integers, texts, records and growing tables") {
  const auto path = temporary_path("typed.h5");
  store::ResultFile file(path, typed_layout(), info());
  std::vector<double> twelve(12);
  for (int i = 0; i < 12; ++i) twelve[i] = 0.1 * i;
  file.write({{"typed", "single", {0, 0}, {4, 3}, store::reals(twelve), {}},
              {"typed", "counts", {1}, {2}, {7, -8}, {}},
              {"typed", "flags", {0}, {1}, {255}, {}},
              {"typed", "names", {2}, {2}, {}, {"two", "three"}},
              {"typed", "members", {0}, {2}, {3, 0.5, 5, 0.25}, {"x + y", "sin(x) * y + 1"}},
              {"typed", "log", {0, 0}, {1, 3}, {1, 2, 3}, {}}},
             progress(1));
  file.publish();
  const auto single = store::read_table(path, "typed/single");
  for (int i = 0; i < 12; ++i) CHECK(single[i] == double(float(0.1 * i)));
  const auto counts = store::read_table(path, "typed/counts");
  CHECK(counts[1] == 7);
  CHECK(counts[2] == -8);
  CHECK(store::read_table(path, "typed/flags")[0] == 255);
  CHECK(store::read_text_table(path, "typed/names") == std::vector<std::string>{"", "", "two", "three"});

  file.write({{"typed", "log", {1, 0}, {2, 3}, {4, 5, 6, 7, 8, 9}, {}}}, progress(2));
  file.publish();
  std::vector<std::uint64_t> dims;
  CHECK(store::read_table(path, "typed/log", &dims) == std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9});
  CHECK(dims == std::vector<std::uint64_t>{3, 3});
}

TEST_CASE("groups nest by their names and tables carry the attributes their kind declares") {
  const auto path = temporary_path("nested.h5");
  store::Group level;
  level.name = "fit/level1";
  level.axes = {{"x", {0, 1}, "x"}};
  level.tables = {{"error", {"x"}, "fit error"}};
  level.tables[0].attributes = {{"role", "error"}, {"anchor", "none"}};
  store::Group sibling = level;
  sibling.name = "fit/level2";
  store::ResultFile file(path, {{level, sibling}}, info());
  file.write({{"fit/level2", "error", {1}, {1}, {0.5}, {}}}, progress(1));
  file.publish();
  CHECK(std::isnan(store::read_table(path, "fit/level2/error")[0]));
  CHECK(store::read_table(path, "fit/level2/error")[1] == 0.5);
  CHECK(store::read_text_attribute(path, "fit/level1/error", "role") == "error");
  CHECK(store::read_text_attribute(path, "fit/level1/error", "description") == "fit error");
  CHECK(store::read_text_attribute(path, "", "job_name") == "test-job");
  CHECK_THROWS_AS(store::read_text_attribute(path, "fit/level1/error", "missing"), RunError);
}

TEST_CASE("readers see only published states: the result file is replaced whole, never written in place") {
  const auto path = temporary_path("published.h5");
  std::filesystem::remove(path);
  store::ResultFile file(path, grid_layout(), info());
  CHECK_FALSE(std::filesystem::exists(path));
  file.write({{"grid", "per_row", {0}, {1}, {1.0}, {}}}, progress(1));
  CHECK_FALSE(std::filesystem::exists(path));
  file.publish();
  CHECK(store::read_table(path, "grid/per_row")[0] == 1.0);
  file.write({{"grid", "per_row", {1}, {1}, {2.0}, {}}}, progress(2));
  CHECK(store::read_table(path, "grid/per_row").size() == 1);  // the second write is not published yet
  file.complete();
  CHECK(store::read_table(path, "grid/per_row") == std::vector<double>{1.0, 2.0});
  CHECK_FALSE(std::filesystem::exists(file.working_path()));
  CHECK_FALSE(temporary_left_beside(path));
}

TEST_CASE("a result file in a directory that cannot be written is refused with the reason") {
  REQUIRE_THROWS_WITH(store::ResultFile("/proc/pbrfit-no/result.h5", grid_layout(), info()),
                      Catch::Matchers::ContainsSubstring("cannot create /proc/pbrfit-no/result.h5.writing: No such file"));
}

TEST_CASE("a block that does not fit its table's declaration is a logic error, not a silent write") {
  const auto path = temporary_path("misfit.h5");
  store::ResultFile file(path, typed_layout(), info());
  CHECK_THROWS_AS(file.write({{"typed", "names", {0}, {1}, {1.0}, {}}}, progress(0)), std::logic_error);
  CHECK_THROWS_AS(file.write({{"typed", "nothing", {0}, {1}, {1.0}, {}}}, progress(0)), std::logic_error);
  CHECK_THROWS_AS(file.write({{"typed", "counts", {0, 0}, {1, 1}, {1.0}, {}}}, progress(0)), std::logic_error);
}

TEST_CASE("a file that is not a pbrfit result is an input error") {
  const auto path = temporary_path("not-hdf5.h5");
  std::ofstream(path) << "plain text";
  REQUIRE_THROWS_WITH(store::read_result_summary(path),
                      Catch::Matchers::StartsWith(path + ": error: not a readable HDF5 file"));
  REQUIRE_THROWS_AS(store::read_result_summary(temporary_path("absent.h5")), InputError);
}

TEST_CASE("the run state is one of four names; any other text in a result file is refused naming the file") {
  for (auto s : {store::RunStatus::running, store::RunStatus::complete, store::RunStatus::interrupted,
                 store::RunStatus::failed})
    CHECK(store::parse_run_status("R.h5", store::run_status_name(s)) == s);
  CHECK_THROWS_WITH(store::parse_run_status("R.h5", "Complete"),
                    Catch::Matchers::ContainsSubstring("R.h5") && Catch::Matchers::ContainsSubstring("'Complete'"));
}

// Integers are written as integers: a uint64 beyond 2^53 and the extremes of int64 arrive exactly (as a
// double they would round), and a real, or an integer the element type cannot hold, is a bug in the kind.
TEST_CASE("integers reach the file exactly; a real or an out-of-range integer in an integer table is refused") {
  const auto path = temporary_path("integers.h5");
  store::Group g;
  g.name = "n";
  g.axes = {{"x", {0, 1}, "x"}};
  g.tables = {{"big", {"x"}, "uint64", ValueType::u64},
              {"rows", {"row"}, "records", ValueType::f64,
               {{"low", ValueType::i64, ""}, {"byte", ValueType::u8, ""}, {"real", ValueType::f64, ""}}, true}};
  store::ResultFile file(path, {{g}}, info());
  const std::uint64_t big = (std::uint64_t(1) << 60) + 1;
  const std::int64_t low = std::numeric_limits<std::int64_t>::min() + 1;
  file.write({{"n", "big", {0}, {2}, {big, std::numeric_limits<std::uint64_t>::max()}, {}},
              {"n", "rows", {0}, {1}, {low, std::uint8_t{200}, 7}, {}}},
             progress(1));
  file.publish();

  const hid_t h5 = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(h5 >= 0);
  std::uint64_t bigs[2] = {};
  const hid_t big_data = H5Dopen2(h5, "n/big", H5P_DEFAULT);
  CHECK(H5Dread(big_data, H5T_NATIVE_UINT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, bigs) >= 0);
  CHECK(bigs[0] == big);
  CHECK(bigs[1] == std::numeric_limits<std::uint64_t>::max());
  H5Dclose(big_data);
  const hid_t rows = H5Dopen2(h5, "n/rows", H5P_DEFAULT);
  const hid_t low_only = H5Tcreate(H5T_COMPOUND, sizeof(std::int64_t));
  H5Tinsert(low_only, "low", 0, H5T_NATIVE_INT64);
  std::int64_t read_low = 0;
  CHECK(H5Dread(rows, low_only, H5S_ALL, H5S_ALL, H5P_DEFAULT, &read_low) >= 0);
  CHECK(read_low == low);
  H5Tclose(low_only);
  H5Dclose(rows);
  H5Fclose(h5);

  const auto refused = [&](store::Block block, const std::string& why) {
    try {
      file.write({std::move(block)}, progress(2));
      FAIL("accepted");
    } catch (const std::logic_error& e) {
      CHECK_THAT(e.what(), Catch::Matchers::ContainsSubstring(why));
    }
  };
  refused({"n", "big", {0}, {1}, {1.0}, {}}, "puts a real into a uint64 element (number 0)");
  refused({"n", "big", {0}, {1}, {-1}, {}}, "puts an integer out of the range of a uint64 element");
  refused({"n", "rows", {1}, {1}, {0, 256, 0.5}, {}}, "puts an integer out of the range of a uint8 element (number 1)");
  refused({"n", "rows", {1}, {1}, {0, 2.0, 0.5}, {}}, "puts a real into a uint8 element (number 1)");
  CHECK(store::read_table(path, "n/big")[0] == double(big));  // nothing of the refused blocks was written
}
