#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <filesystem>
#include <limits>
#include <fstream>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/block_journal.hpp"
#include "store_test_paths.hpp"

using namespace pbrfit;
using Catch::Matchers::ContainsSubstring;
using store::ValueType;

namespace {

store::ResultLayout layout() {
  store::Group g;
  g.name = "g";
  g.axes = {{"x", {0, 1, 2}, "x"}, {"y", {0, 1}, "y"}};
  g.tables = {{"half", {"x", "y"}, "", ValueType::f32},
              {"full", {"x"}, "", ValueType::f64},
              {"rows", {"row"}, "", ValueType::f64, {{"name", ValueType::text, ""}, {"v", ValueType::i64, ""}}, true}};
  return {{g}};
}

std::vector<store::Block> blocks() {
  return {{"g", "half", {1, 0}, {2, 2}, {0.1, 0.2, 0.3, 0.4}, {}},
          {"g", "full", {0}, {3}, {0.1, 1e300, -2.0}, {}},
          {"g", "rows", {5}, {2}, {1, 2}, {"a", "bc"}}};
}

Bytes encode(const store::BlockCodec& codec, const std::vector<store::Block>& list) {
  ByteWriter out;
  for (const auto& b : list) codec.encode(out, b);
  return out.take();
}

}  // namespace

TEST_CASE("blocks survive encoding, float32 tables at float32 precision") {
  const store::BlockCodec codec(layout());
  const Bytes bytes = encode(codec, blocks());
  ByteReader in(bytes);
  const auto half = codec.decode(in);
  CHECK(half.values == store::reals(std::vector<double>{float(0.1), float(0.2), float(0.3), float(0.4)}));
  CHECK(half.offset == std::vector<std::uint64_t>{1, 0});
  const auto full = codec.decode(in);
  CHECK(full.values == blocks()[1].values);
  const auto rows = codec.decode(in);
  CHECK(rows.texts == blocks()[2].texts);
  CHECK(rows.values == blocks()[2].values);
  CHECK(in.remaining() == 0);
}

TEST_CASE("decoding refuses blocks the layout cannot hold") {
  const store::BlockCodec codec(layout());
  const auto refused = [&](store::Block b) {
    ByteWriter out;
    out.put_varint(b.table == "half" ? 0 : b.table == "full" ? 1 : 7);
    for (auto o : b.offset) out.put_varint(o);
    for (auto c : b.count) out.put_varint(c);
    for (const auto& v : b.values) out.put(v.real());
    ByteReader in(out.bytes());
    CHECK_THROWS_AS(codec.decode(in), ByteFormatError);
  };
  refused({"g", "full", {2}, {2}, {1, 2}, {}});         // beyond the axis
  refused({"g", "full", {0}, {4}, {1, 2, 3, 4}, {}});    // more cells than the axis
  refused({"g", "unknown", {0}, {1}, {1}, {}});         // no such table
  refused({"g", "full", {0}, {3}, {1, 2}, {}});         // fewer values than cells
}

TEST_CASE("integers pass the codec exactly and compactly; an integer its type cannot hold is refused") {
  store::Group g;
  g.name = "g";
  g.axes = {{"x", {0, 1, 2}, "x"}};
  g.tables = {{"big", {"x"}, "", ValueType::u64}, {"small", {"x"}, "", ValueType::u8},
              {"signed", {"x"}, "", ValueType::i32}};
  const store::BlockCodec codec({{g}});
  const std::vector<store::Block> blocks = {
      {"g", "big", {0}, {3}, {std::uint64_t{0}, (std::uint64_t(1) << 60) + 1, ~std::uint64_t{0}}, {}},
      {"g", "small", {0}, {3}, {std::uint8_t{0}, std::uint8_t{7}, std::uint8_t{255}}, {}},
      {"g", "signed", {0}, {3}, {-1, std::numeric_limits<std::int32_t>::min(), 5}, {}}};
  const Bytes bytes = encode(codec, blocks);
  CHECK(bytes.size() < 3 * (3 + 3 * sizeof(double)));  // varints, not eight bytes a value
  ByteReader in(bytes);
  for (const auto& block : blocks) {
    const auto decoded = codec.decode(in);
    CHECK(decoded.values == block.values);
    for (const auto& v : decoded.values) CHECK(v.is_integer());
  }
  ByteWriter crafted;
  for (const std::uint64_t v : {std::uint64_t{1}, std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{256}})
    crafted.put_varint(v);  // table 1 (uint8), offset 0, one value: 256
  ByteReader crafted_in(crafted.bytes());
  CHECK_THROWS_WITH(codec.decode(crafted_in), ContainsSubstring("value out of range for uint8"));
}

TEST_CASE("the journal replays exactly the blocks up to the length a checkpoint relies on") {
  const auto path = temporary_path("journal");
  const store::BlockCodec codec(layout());
  auto journal = store::BlockJournal::create(path, "job text");
  const auto empty = journal.length();
  journal.append(3, encode(codec, blocks()));
  const auto first = journal.length();
  journal.append(1, encode(codec, {blocks()[1]}));
  const auto second = journal.length();

  std::size_t seen = 0;
  store::replay_block_journal(path, "job text", codec, first, [&](store::Block) { ++seen; });
  CHECK(seen == 3);
  seen = 0;
  store::replay_block_journal(path, "job text", codec, second, [&](store::Block) { ++seen; });
  CHECK(seen == 4);
  seen = 0;
  store::replay_block_journal(path, "job text", codec, empty, [&](store::Block) { ++seen; });
  CHECK(seen == 0);

  REQUIRE_THROWS_WITH(store::replay_block_journal(path, "other text", codec, first, [](store::Block) {}),
                      ContainsSubstring("belongs to a different job text"));
  REQUIRE_THROWS_WITH(store::replay_block_journal(path, "job text", codec, second + 1, [](store::Block) {}),
                      ContainsSubstring("shorter than the checkpoint that refers to it"));
  REQUIRE_THROWS_WITH(store::replay_block_journal(path, "job text", codec, first + 3, [](store::Block) {}),
                      ContainsSubstring("damaged block journal"));

  // Continuing after `first` cuts off the second batch; what comes next follows the first.
  auto again = store::BlockJournal::reopen(path, first);
  again.append(1, encode(codec, {blocks()[0]}));
  seen = 0;
  store::replay_block_journal(path, "job text", codec, again.length(), [&](store::Block b) {
    ++seen;
    if (seen == 4) CHECK(b.table == "half");
  });
  CHECK(seen == 4);
}
