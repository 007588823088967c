#include <catch2/catch_test_macros.hpp>

#include <limits>

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

TEST_CASE("empty arrays and strings round-trip (no memcpy from an empty vector's null data)") {
  // Under UndefinedBehaviorSanitizer this reproduces the report the quickstart job first hit in
  // Coordinator::begin_stage: memcpy to the null data() of an empty vector.
  ByteWriter out;
  out.put_array(std::span<const double>());
  out.put_string("");
  out.put_bytes(Bytes{});
  const Bytes bytes = out.take();
  ByteReader in(bytes);
  CHECK(in.get_array<double>().empty());
  CHECK(in.get_string().empty());
  CHECK(in.get_bytes().empty());
  CHECK(in.remaining() == 0);
}

TEST_CASE("variable-length integers round-trip, small magnitudes in one byte") {
  const std::vector<std::int64_t> values = {0, -1, 1, -64, 63, -65, std::numeric_limits<std::int64_t>::min(),
                                            std::numeric_limits<std::int64_t>::max()};
  ByteWriter out;
  for (const auto v : values) out.put_signed_varint(v);
  out.put_varint(std::numeric_limits<std::uint64_t>::max());
  const Bytes bytes = out.take();
  CHECK(bytes.size() == 1 + 1 + 1 + 1 + 1 + 2 + 10 + 10 + 10);
  ByteReader in(bytes);
  for (const auto v : values) CHECK(in.get_signed_varint() == v);
  CHECK(in.get_varint() == std::numeric_limits<std::uint64_t>::max());
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
