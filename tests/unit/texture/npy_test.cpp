// NumPy .npy read back by numpy itself (Debian's, in a child /usr/bin/python3): dtype, shape, C order, and
// every value bitwise ('<f4': the float cast; '<f2': Imath's half).
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <sstream>

#include "pbrfit/texture/npy.hpp"
#include "texture_test_support.hpp"

using namespace pbrfit;
using namespace pbrfit::texture;

namespace {

constexpr const char* reader = R"(import sys, numpy
for path in sys.argv[1:]:
    a = numpy.load(path, allow_pickle=False)
    with open(path, 'rb') as f:
        head = f.read(10)
    print(a.dtype.str, a.flags['C_CONTIGUOUS'], head[6], head[7], (10 + head[8] + 256 * head[9]) % 64)
    print(' '.join(str(n) for n in a.shape))
    print(' '.join(str(int(w)) for w in a.view('<u%d' % a.dtype.itemsize).ravel()))
)";

}  // namespace

TEST_CASE("NPY: numpy loads the dtype, the shape without unit layers and depth, and every value") {
  struct Case {
    Texture t;
    Precision p;
    std::string shape;
  };
  const std::vector<Case> cases = {
      {testing::sample(5, 3, 4), Precision::f32, "3 5 4"},
      {testing::sample(5, 3, 1, testing::Values::awkward, 1, 1, 1, 2), Precision::f16, "3 5 1"},
      {testing::sample(4, 2, 2, testing::Values::awkward, 1, 3, 1, 3), Precision::f32, "3 2 4 2"},
      {testing::sample(2, 3, 3, testing::Values::awkward, 4, 1, 1, 4), Precision::f16, "4 3 2 3"},
      {testing::sample(64, 1, 2, testing::Values::awkward, 1, 1, 1, 5), Precision::f32, "1 64 2"},
  };
  std::string command = "/usr/bin/python3 " + testing::shell_quoted(testing::scratch("read_npy.py").string());
  testing::write_file(testing::scratch("read_npy.py"), std::string(reader));
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto path = testing::scratch("t" + std::to_string(k) + ".npy");
    testing::write_file(path, encode_npy(cases[k].t, cases[k].p));
    command += " " + testing::shell_quoted(path.string());
  }
  const auto result = testing::run(command);
  INFO(result.errors);
  REQUIRE(result.status == 0);
  std::istringstream lines(result.output);
  for (const Case& c : cases) {
    std::string line;
    REQUIRE(std::getline(lines, line));
    CHECK(line == (c.p == Precision::f32 ? "<f4" : "<f2") + std::string(" True 1 0 0"));  // version 1.0, 64-aligned
    REQUIRE(std::getline(lines, line));
    CHECK(line == c.shape);
    REQUIRE(std::getline(lines, line));
    std::istringstream words(line);
    std::size_t count = 0, mismatches = 0;
    for (std::uint64_t w; words >> w; ++count)
      mismatches += w != (c.p == Precision::f32 ? testing::f32_bits(c.t.values.at(count))
                                                : testing::f16_bits(c.t.values.at(count)));
    CHECK(count == c.t.values.size());
    CHECK(mismatches == 0);
  }
}

TEST_CASE("NPY: the header is NumPy's dictionary, padded with spaces to 64 bytes") {
  const Bytes b = encode_npy(testing::sample(5, 3, 4), Precision::f32);
  CHECK(testing::text(b, 0, 6) == "\x93NUMPY");
  CHECK(testing::u16(b, 8) == 118);
  CHECK(testing::text(b, 10, 118) ==
        "{'descr': '<f4', 'fortran_order': False, 'shape': (3, 5, 4), }" + std::string(55, ' ') + "\n");
}

TEST_CASE("NPY: mips are refused") {
  CHECK_THROWS_WITH(encode_npy(testing::sample(4, 4, 2, testing::Values::awkward, 1, 1, 3), Precision::f32),
                    Catch::Matchers::Equals("npy: holds one mip level, not 3"));
}
