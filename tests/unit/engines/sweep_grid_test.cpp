// Sweep grids: axis samples, levels of a hierarchy, nearest parents and the fitting schedule.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "pbrfit/sweep/hierarchy.hpp"
#include "pbrfit/sweep/level_grid.hpp"
#include "pbrfit/sweep/sweep_schedule.hpp"

using namespace pbrfit::sweep;

namespace {

GridAxis edges(const char* name, std::size_t count, double lower = 0.0, double upper = 1.0) {
  return {name, lower, upper, count, Placement::edges};
}

std::vector<std::size_t> counts(const LevelGrid& grid) {
  std::vector<std::size_t> out;
  for (const auto& axis : grid.axes()) out.push_back(axis.count);
  return out;
}

}  // namespace

TEST_CASE("axes sample their range at edges or at cell centres") {
  CHECK(edges("r", 5).values() == std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0});
  CHECK(GridAxis{"c", 0.0, 1.0, 4, Placement::centres}.values() == std::vector<double>{0.125, 0.375, 0.625, 0.875});
  CHECK(edges("r", 7, 0.1, 0.7).values().back() == 0.7);
  CHECK(GridAxis{"fixed", 0.3, 0.3, 1, Placement::edges}.values() == std::vector<double>{0.3});
  CHECK_THROWS_AS(validate(edges("one", 1)), std::invalid_argument);
  CHECK_THROWS_AS(validate(edges("backwards", 3, 1.0, 0.0)), std::invalid_argument);
  CHECK_THROWS_AS(validate(GridAxis{"none", 0, 1, 0, Placement::centres}), std::invalid_argument);
  CHECK(invalid_reason(edges("one", 1)) == "axis 'one' needs at least 2 samples at cell edges");
  CHECK(invalid_reason(edges("r", 5)).empty());
}

TEST_CASE("cells are numbered row-major, the last axis fastest") {
  const LevelGrid grid({edges("a", 3), edges("b", 4)});
  CHECK(grid.cell_count() == 12);
  CHECK(grid.indices(7) == std::vector<std::size_t>{1, 3});
  const std::vector<std::size_t> at = {2, 1};
  CHECK(grid.flat_index(at) == 9);
  CHECK(grid.coordinates(7) == std::vector<double>{0.5, 1.0});
}

TEST_CASE("each coarser level halves every axis that can be halved") {
  const std::vector<GridAxis> finest = {edges("r", 64), GridAxis{"v", 0, 1, 16, Placement::centres}, edges("k", 2)};
  CHECK(max_level_count(finest) == 7);
  const auto levels = hierarchy(finest, 7);
  CHECK(counts(levels[0]) == std::vector<std::size_t>{2, 1, 2});
  CHECK(counts(levels[1]) == std::vector<std::size_t>{3, 1, 2});
  CHECK(counts(levels[3]) == std::vector<std::size_t>{9, 2, 2});
  CHECK(counts(levels[5]) == std::vector<std::size_t>{33, 8, 2});
  CHECK(counts(levels[6]) == std::vector<std::size_t>{64, 16, 2});
  CHECK(counts(hierarchy(finest, 2)[0]) == std::vector<std::size_t>{33, 8, 2});
  CHECK_THROWS_AS(hierarchy(finest, 8), std::invalid_argument);
  CHECK_THROWS_AS(hierarchy(finest, 0), std::invalid_argument);
}

TEST_CASE("a fine cell's parent is the coarse cell nearest on every axis") {
  const LevelGrid fine({edges("a", 9), edges("b", 5)});
  const LevelGrid coarse({edges("a", 5), edges("b", 3)});
  for (std::size_t c = 0; c < fine.cell_count(); ++c) {
    const auto p = coarse.coordinates(nearest_parent(fine, c, coarse));
    const auto x = fine.coordinates(c);
    for (std::size_t d = 0; d < 2; ++d)
      for (double v : coarse.axes()[d].values()) CHECK(std::abs(p[d] - x[d]) <= std::abs(v - x[d]) + 1e-15);
  }
  const std::vector<std::size_t> corner = {8, 4};
  CHECK(nearest_parent(fine, fine.flat_index(corner), coarse) == coarse.cell_count() - 1);
}

TEST_CASE("the nearest parent is the first nearest coarse node, found without scanning every node") {
  // The search against a scan of every node (the first of the nearest wins), on axes of edges and centres,
  // ranges with exactly representable and rounded nodes, and a range so narrow that nodes repeat.
  const auto scanned = [](const GridAxis& coarse, double x) {
    std::size_t best = 0;
    for (std::size_t j = 1; j < coarse.count; ++j)
      if (std::abs(coarse.value(j) - x) < std::abs(coarse.value(best) - x)) best = j;
    return best;
  };
  for (Placement placement : {Placement::edges, Placement::centres})
    for (auto [lower, upper] : {std::pair{0.0, 1.0}, std::pair{0.1, 0.7}, std::pair{-3.0, 1e-3}, std::pair{1.0, 1.0 + 4e-15}})
      for (std::size_t count = 2; count <= 40; ++count)
        for (std::size_t coarse_count = placement == Placement::edges ? 2 : 1; coarse_count <= count; ++coarse_count) {
          const GridAxis f{"x", lower, upper, count, placement}, c{"x", lower, upper, coarse_count, placement};
          const LevelGrid fine({f}), coarse({c});
          for (std::size_t cell = 0; cell < count; ++cell)
            REQUIRE(nearest_parent(fine, cell, coarse) == scanned(c, f.value(cell)));
        }
  // A fine level of 2^20 cells maps to its parents in a moment (the scan took minutes of validation).
  const auto levels = hierarchy({edges("x", std::size_t{1} << 20)}, 2);
  CHECK(nearest_parent(levels[1], levels[1].cell_count() - 1, levels[0]) == levels[0].cell_count() - 1);
  CHECK(nearest_parent(levels[1], 2, levels[0]) == 1);
}

TEST_CASE("a schedule lists every cell once, after all of its sources, and knows their last readers") {
  for (bool reverse : {false, true}) {
    const auto levels = hierarchy({edges("r", 9), edges("v", 5)}, 3);
    const SweepSchedule schedule(levels, Marching{1, reverse});
    std::set<std::pair<std::uint32_t, std::size_t>> seen;
    for (std::uint32_t s = 0; s < schedule.stage_count(); ++s) {
      for (std::size_t item = 0; item < schedule.stages()[s].cells.size(); ++item) {
        const CellRef cell = schedule.cell_of(s, item);
        CHECK(seen.insert({cell.level, cell.cell}).second);
        CHECK(schedule.stage_of(cell) == s);
        CHECK(schedule.item_of(cell) == item);
        for (const CellRef& source : schedule.sources(cell)) {
          CHECK(schedule.stage_of(source) < s);
          CHECK(schedule.last_reader(source) >= s);
        }
      }
    }
    std::size_t total = 0;
    for (const auto& level : levels) total += level.cell_count();
    CHECK(seen.size() == total);
    CHECK(schedule.stage_count() == 2 + 3 + 5);  // one stage per view index on each level
  }
}

TEST_CASE("marching warm-starts from the neighbour one step back, then from the parent") {
  const auto levels = hierarchy({edges("r", 3), edges("v", 5)}, 2);
  const SweepSchedule forward(levels, Marching{1, false});
  const std::vector<std::size_t> at = {1, 2};
  const CellRef cell{1, levels[1].flat_index(at)};
  const auto sources = forward.sources(cell);
  REQUIRE(sources.size() == 2);
  CHECK(levels[1].indices(sources[0].cell) == std::vector<std::size_t>{1, 1});
  CHECK(sources[1].level == 0);
  const SweepSchedule backward(levels, Marching{1, true});
  CHECK(levels[1].indices(backward.sources(cell)[0].cell) == std::vector<std::size_t>{1, 3});
  const SweepSchedule flat({levels[1]}, std::nullopt);
  CHECK(flat.stage_count() == 1);
  CHECK(flat.sources(CellRef{0, 4}).empty());
  CHECK(flat.last_reader(CellRef{0, 4}) == 0);
}
