// merge_touching_blocks directly: the order it returns, what it merges, and that a later block for the same
// cells stays later — by 64-bit positions, and by comparing offsets where a position would not fit.
#include <catch2/catch_test_macros.hpp>

#include <cstdint>
#include <vector>

#include "block_merge.hpp"

using namespace pbrfit;

namespace {

store::Block cell(std::vector<std::uint64_t> offset, double value) {
  const std::vector<std::uint64_t> count(offset.size(), 1);
  return {"g", "t", std::move(offset), count, {value}, {}};
}

std::vector<double> values_of(const std::vector<store::Block>& blocks) {
  std::vector<double> out;
  for (const auto& b : blocks)
    for (const auto& v : b.values) out.push_back(v.real());
  return out;
}

}  // namespace

TEST_CASE("merged blocks come out in offset order, lines joined, the later of two blocks for one cell after") {
  // A 3 x 4 table, cells given out of order, (1, 2) twice: 5 first, then 50.
  std::vector<store::Block> blocks = {cell({1, 2}, 5), cell({0, 1}, 1), cell({2, 0}, 8), cell({0, 0}, 0),
                                      cell({1, 2}, 50), cell({1, 1}, 4), cell({1, 3}, 6), cell({0, 2}, 2)};
  const auto merged = store::merge_touching_blocks(blocks, {0, 4});
  CHECK(values_of(merged) == std::vector<double>{0, 1, 2, 4, 5, 50, 6, 8});
  REQUIRE(merged.size() == 4);  // (0, 0..2), (1, 1..2) with 5, (1, 2..3) with 50, (2, 0)
  CHECK(merged[0].offset == std::vector<std::uint64_t>{0, 0});
  CHECK(merged[0].count == std::vector<std::uint64_t>{1, 3});
  CHECK(merged[1].count == std::vector<std::uint64_t>{1, 2});
  CHECK(merged[2].offset == std::vector<std::uint64_t>{1, 2});
  CHECK(merged[3].offset == std::vector<std::uint64_t>{2, 0});
}

TEST_CASE("whole rows in order merge into one block without moving") {
  std::vector<store::Block> rows;
  for (std::uint64_t r = 0; r < 5; ++r) rows.push_back({"g", "t", {r, 0}, {1, 2}, {double(2 * r), double(2 * r + 1)}, {}});
  const auto merged = store::merge_touching_blocks(rows, {0, 2});
  REQUIRE(merged.size() == 1);
  CHECK(merged[0].count == std::vector<std::uint64_t>{5, 2});
  CHECK(values_of(merged) == std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
}

TEST_CASE("where a position would overflow 64 bits the blocks are ordered by their offsets, the same way") {
  // Extents of 2^40 along two inner dimensions: the row-major position of (1, 0, 0) is 2^80.
  const std::uint64_t big = std::uint64_t{1} << 40;
  std::vector<store::Block> blocks = {cell({1, 0, 0}, 3), cell({0, big - 1, 7}, 2), cell({0, 0, 1}, 1),
                                      cell({1, 0, 0}, 30), cell({0, 0, 0}, 0)};
  const auto merged = store::merge_touching_blocks(blocks, {0, big, big});
  CHECK(values_of(merged) == std::vector<double>{0, 1, 2, 3, 30});
  REQUIRE(merged.size() == 4);  // (0, 0, 0..1) joined; (1, 0, 0) twice, 3 before 30
  CHECK(merged[0].count == std::vector<std::uint64_t>{1, 1, 2});
  CHECK(merged[3].offset == std::vector<std::uint64_t>{1, 0, 0});
  CHECK(merged[3].values[0].real() == 30);
}
