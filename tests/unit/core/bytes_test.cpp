#include <catch2/catch_test_macros.hpp>

#include "pbrfit/core/bytes.hpp"

using namespace pbrfit;

TEST_CASE("bytes round-trip values, arrays and strings") {
  ByteWriter out;
  out.put<std::uint32_t>(7);
  out.put(2.5);
  const std::vector<double> values = {1.0, -0.0, 1e-300};
  out.put_array(std::span<const double>(values));
  out.put_string("héllo");
  const Bytes bytes = out.take();

  ByteReader in(bytes);
  CHECK(in.get<std::uint32_t>() == 7);
  CHECK(in.get<double>() == 2.5);
  CHECK(in.get_array<double>() == values);
  CHECK(in.get_string() == "héllo");
  CHECK(in.remaining() == 0);
}

TEST_CASE("reading past the end is an error with its offset, never a crash") {
  ByteWriter out;
  out.put<std::uint64_t>(1'000'000);  // claims a million elements that are not there
  const Bytes bytes = out.take();
  ByteReader in(bytes);
  try {
    in.get_array<double>();
    FAIL("expected ByteFormatError");
  } catch (const ByteFormatError& e) {
    CHECK(e.offset() == 8);
  }
  ByteReader empty(std::span<const std::byte>{});
  CHECK_THROWS_AS(empty.get<int>(), ByteFormatError);
}

TEST_CASE("FNV-1a matches its published test vectors") {
  auto hash = [](const std::string& s) {
    return fnv1a64(std::span(reinterpret_cast<const std::byte*>(s.data()), s.size()));
  };
  CHECK(hash("") == 0xcbf29ce484222325ULL);
  CHECK(hash("a") == 0xaf63dc4c8601ec8cULL);
  CHECK(hash("foobar") == 0x85944171f73967e8ULL);
}
