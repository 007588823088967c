// core/serial.hpp: every supported shape round-trips, arithmetic vectors keep the hand-written layout, and
// a buffer that is short, long or implausible is an error, never a crash or a huge allocation.
#include <catch2/catch_test_macros.hpp>

#include <array>
#include <optional>

#include "pbrfit/core/serial.hpp"

using namespace pbrfit;

namespace {

enum class Colour : std::uint8_t { red = 1, green = 2 };

struct Inner {
  std::string name;
  std::vector<float> weights;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(name, weights);
  }
  bool operator==(const Inner&) const = default;
};

struct Outer {
  std::uint64_t count = 0;
  double value = 0.0;
  bool flag = false;
  Colour colour = Colour::red;
  std::vector<Inner> inners;
  std::array<std::int32_t, 3> triple{};
  std::optional<Inner> maybe;
  std::pair<std::uint32_t, std::vector<bool>> pair;
  Bytes raw;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(count, value, flag, colour, inners, triple, maybe, pair, raw);
  }
  bool operator==(const Outer& o) const {
    return count == o.count && value == o.value && flag == o.flag && colour == o.colour && inners == o.inners &&
           triple == o.triple && maybe == o.maybe && pair == o.pair && raw == o.raw;
  }
};

}  // namespace

TEST_CASE("serial round-trips nested structs, vectors, arrays, optionals and enums") {
  Outer a;
  a.count = (std::uint64_t(1) << 63) + 5;  // integers stay integers: beyond what a double holds exactly
  a.value = -0.0;
  a.flag = true;
  a.colour = Colour::green;
  a.inners = {{"first", {1.5f, -2.0f}}, {"", {}}};
  a.triple = {-1, 0, 7};
  a.maybe = Inner{"m", {3.0f}};
  a.pair = {9, {true, false, true}};
  a.raw = {std::byte{0}, std::byte{255}};
  const Bytes bytes = to_bytes(a);
  const Outer b = from_bytes<Outer>(bytes);
  CHECK(b == a);
  CHECK(b.count == (std::uint64_t(1) << 63) + 5);
  CHECK(!from_bytes<Outer>(to_bytes(Outer{})).maybe.has_value());
}

TEST_CASE("a vector of doubles is written as ByteWriter::put_array writes it") {
  const std::vector<double> values = {1.0, 2.5, 1e-300};
  ByteWriter hand;
  hand.put_array(std::span<const double>(values));
  CHECK(to_bytes(values) == hand.bytes());
  CHECK(from_bytes<std::vector<double>>(hand.bytes()) == values);
}

TEST_CASE("bad buffers are ByteFormatErrors") {
  const Bytes bytes = to_bytes(std::vector<Inner>{{"abc", {1.0f}}});
  SECTION("short") {
    const Bytes cut(bytes.begin(), bytes.end() - 1);
    CHECK_THROWS_AS(from_bytes<std::vector<Inner>>(cut), ByteFormatError);
  }
  SECTION("long") {
    Bytes longer = bytes;
    longer.push_back(std::byte{0});
    CHECK_THROWS_AS(from_bytes<std::vector<Inner>>(longer), ByteFormatError);
  }
  SECTION("a count of structs beyond the data, refused before allocating") {
    ByteWriter out;
    out.put<std::uint64_t>(std::uint64_t(1) << 60);
    CHECK_THROWS_AS(from_bytes<std::vector<Inner>>(out.bytes()), ByteFormatError);
  }
  SECTION("a boolean that is neither 0 nor 1") {
    const Bytes two = {std::byte{2}};
    CHECK_THROWS_AS(from_bytes<bool>(two), ByteFormatError);
  }
  SECTION("nothing is an empty buffer") {
    CHECK(to_bytes(Nothing{}).empty());
    CHECK_NOTHROW(from_bytes<Nothing>(Bytes{}));
  }
}
