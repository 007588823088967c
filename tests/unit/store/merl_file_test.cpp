// MERL .binary files: written and read back, and every malformed file refused naming it.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cstring>
#include <fstream>
#include <limits>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/merl_file.hpp"
#include "store_test_paths.hpp"

using namespace pbrfit;
using Catch::Matchers::ContainsSubstring;

namespace {

std::string refusal(const std::string& path) {
  try {
    store::read_merl_file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

void write_raw(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

}  // namespace

TEST_CASE("a MERL file is written atomically and read back bit for bit") {
  const auto path = temporary_path("table.binary");
  std::vector<double> values(store::merl_value_count);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = double(i % 977) - 3.0;  // negatives are missing cells
  store::write_merl_file(path, values);
  CHECK(store::read_merl_file(path) == values);
}

TEST_CASE("malformed MERL files are refused with the file and the reason") {
  const auto path = temporary_path("bad.binary");
  write_raw(path, std::string(100, '\0'));
  CHECK_THAT(refusal(path), ContainsSubstring("is 100 bytes long; a MERL file has 34992012"));
  std::string wrong(store::merl_file_bytes, '\0');
  const std::int32_t dims[3] = {90, 90, 90};
  std::memcpy(wrong.data(), dims, sizeof dims);
  write_raw(path, wrong);
  CHECK_THAT(refusal(path), ContainsSubstring("has the dimensions 90 x 90 x 90; a MERL file has 90 x 90 x 180"));
  const std::int32_t good[3] = {90, 90, 180};
  std::memcpy(wrong.data(), good, sizeof good);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::memcpy(wrong.data() + 12 + 8 * 1458001, &nan, 8);
  write_raw(path, wrong);
  CHECK_THAT(refusal(path), ContainsSubstring("not a finite number at byte 11664020 (green channel, cell 1)"));
  CHECK_THAT(refusal(temporary_path("missing.binary")), ContainsSubstring("cannot read file"));
  write_raw(path, wrong + "x");
  CHECK_THAT(refusal(path), ContainsSubstring("is too large"));
}
