// Symbolic regression's data: rows of a CSV file held out by test_fraction (issue 24), chosen by
// sample_seed, every row in exactly one part, and refusals at the key.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "pbrfit/core/error.hpp"
#include "pbrfit/jobs/symreg/symreg_data.hpp"

using namespace pbrfit::jobs::symreg;
using Catch::Matchers::ContainsSubstring;

namespace {

// 100 rows, y = 2x, x = 0 .. 99.
std::string line_file() {
  const auto path = (std::filesystem::temp_directory_path() / "pbrfit-symreg-data-test.csv").string();
  std::ofstream out(path);
  out << "x,y\n";
  for (int i = 0; i < 100; ++i) out << i << "," << 2 * i << "\n";
  return path;
}

DatasetSection csv_section(double fraction, std::uint64_t seed) {
  DatasetSection s;
  s.csv = {line_file(), true, "csv", {"job.yaml", 3, 4}};
  s.inputs = {{"x"}, true, "inputs", {"job.yaml", 4, 4}};
  s.targets = {{"y"}, true, "targets", {"job.yaml", 5, 4}};
  s.test_fraction = {fraction, fraction != 0.0, "test_fraction", {"job.yaml", 6, 4}};
  s.sample_seed = seed;
  return s;
}

std::vector<double> column(const pbrfit::gp::Dataset& d) {
  return {d.inputs.col(0).data(), d.inputs.col(0).data() + d.inputs.rows()};
}

}  // namespace

TEST_CASE("test_fraction holds out a seeded share of a file's rows, each row in one part, in file order", "[symreg]") {
  const auto data = load_symreg_data(csv_section(0.3, 1), {"job.yaml", 2, 2});
  const auto& out = data->outputs.at(0);
  REQUIRE(out.train.rows() == 70);
  REQUIRE(out.test.rows() == 30);
  const auto train = column(out.train), test = column(out.test);
  CHECK(std::is_sorted(train.begin(), train.end()));
  CHECK(std::is_sorted(test.begin(), test.end()));
  std::set<double> all(train.begin(), train.end());
  all.insert(test.begin(), test.end());
  CHECK(all.size() == 100);
  CHECK((out.test.target == 2.0 * out.test.inputs.col(0).array()).all());  // rows stay whole
  CHECK(column(load_symreg_data(csv_section(0.3, 1), {})->outputs[0].test) == test);  // the seed decides
  CHECK(column(load_symreg_data(csv_section(0.3, 2), {})->outputs[0].test) != test);
  CHECK(load_symreg_data(csv_section(0.0, 1), {})->outputs[0].test.rows() == 0);  // the default: none
}

TEST_CASE("test_fraction is refused where it cannot apply", "[symreg]") {
  DatasetSection generator;
  generator.generator = {"nguyen5", true, "generator", {"job.yaml", 3, 4}};
  generator.test_fraction = {0.2, true, "test_fraction", {"job.yaml", 6, 4}};
  CHECK_THROWS_WITH(load_symreg_data(generator, {}),
                    "job.yaml:6:4: error: 'test_fraction' is for csv and result data; a generator draws fresh test "
                    "points (test_points)");
  DatasetSection few = csv_section(0.9, 1);
  std::ofstream(few.csv.value) << "x,y\n1,2\n2,4\n3,6\n4,8\n5,10\n";
  CHECK_THROWS_WITH(load_symreg_data(few, {}),
                    ContainsSubstring("'test_fraction' leaves output 'y' fewer than 2 training rows (of 5)"));
}
