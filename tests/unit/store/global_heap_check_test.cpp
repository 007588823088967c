#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>

#include "global_heap_check.hpp"
#include "pbrfit/core/error.hpp"
#include "store_test_paths.hpp"

using pbrfit::store::check_global_heaps;

namespace {

const std::string regression =
    std::string(PBRFIT_SOURCE_DIR) + "/tests/fuzz/regressions/result_file/hdf5-global-heap-free-space-of-size-0.h5";

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

void put_u64(std::string& bytes, std::size_t at, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xff);
}

}  // namespace

// The fuzzer's file: its collection at byte 56500 (4096 bytes) ends in a free-space object of size 0 at
// 56556, on which HDF5 1.10.8 loops forever.
TEST_CASE("A global heap collection HDF5 would loop on is refused, naming its byte", "[store]") {
  CHECK_THROWS_WITH(check_global_heaps(regression), Catch::Matchers::ContainsSubstring("at byte 56500"));
  CHECK_THROWS_AS(check_global_heaps(regression), pbrfit::RunError);
}

TEST_CASE("The same collection with its free space's true size passes", "[store]") {
  std::string bytes = bytes_of(regression);
  REQUIRE(bytes.substr(56500, 4) == "GCOL");
  put_u64(bytes, 56556 + 8, 56500 + 4096 - 56556);  // the free space covers the rest of the collection
  const std::string repaired = temporary_path("global-heap-repaired.h5");
  write_bytes(repaired, bytes);
  CHECK_NOTHROW(check_global_heaps(repaired));
  put_u64(bytes, 56556 + 8, ~std::uint64_t(0) - 7);  // a size that wraps the walk backwards
  write_bytes(repaired, bytes);
  CHECK_THROWS_AS(check_global_heaps(repaired), pbrfit::RunError);
}

TEST_CASE("Files the check cannot read are left to HDF5's open", "[store]") {
  CHECK_NOTHROW(check_global_heaps(temporary_path("no-such-file.h5")));
  CHECK_NOTHROW(check_global_heaps(std::filesystem::temp_directory_path().string()));
}

// The fuzzer's second file: object 5 of the collection at byte 2048 claims 193 GB, which HDF5 1.10.8
// copies from the collection's buffer (ASan: memcpy past it).
TEST_CASE("A global heap object larger than its collection is refused", "[store]") {
  const std::string past = std::string(PBRFIT_SOURCE_DIR) +
                           "/tests/fuzz/regressions/result_file/hdf5-global-heap-object-past-its-collection.h5";
  CHECK_THROWS_WITH(check_global_heaps(past), Catch::Matchers::ContainsSubstring("at byte 2048"));
}

// An intact collection whose first object's data reads like a damaged collection: taken for data, as
// HDF5 allocates collections side by side (walking it would refuse the file; skipping keeps the check linear).
TEST_CASE("A collection inside an intact one is its data, not walked", "[store]") {
  std::string bytes(8192, '\0');
  const auto put_header = [&](std::size_t at, std::uint64_t size) {
    bytes.replace(at, 5, std::string("GCOL\x01", 5));
    put_u64(bytes, at + 8, size);
  };
  put_header(0, 8192);
  bytes[16] = 1;             // object 1 ...
  put_u64(bytes, 24, 32);    // ... of 32 bytes at 32
  put_header(32, 48);        // its data: a "collection" whose first object (at 48: index 0, size 0) loops
  put_u64(bytes, 64 + 8, 8192 - 64);  // the free space, index 0, the rest
  const std::string path = temporary_path("global-heap-nested.h5");
  write_bytes(path, bytes);
  CHECK_NOTHROW(check_global_heaps(path));
  bytes.replace(0, 4, "XXXX");  // without the outer collection the inner one is walked, and refused
  write_bytes(path, bytes);
  CHECK_THROWS_WITH(check_global_heaps(path), Catch::Matchers::ContainsSubstring("at byte 32"));
}
