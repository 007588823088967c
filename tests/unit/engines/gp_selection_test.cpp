#include <algorithm>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/pareto.hpp"
#include "pbrfit/gp/variation.hpp"

using namespace pbrfit::gp;
using pbrfit::RandomStream;

namespace {

Fitness point(double error, double cost, double piecewise = 0.0) { return {error, cost, piecewise, true}; }

std::vector<Fitness> random_points(std::size_t count, std::uint64_t seed, bool coarse) {
  RandomStream random(seed, 0);
  std::vector<Fitness> points;
  for (std::size_t i = 0; i < count; ++i) {
    const double error = coarse ? static_cast<double>(random.below(6)) : random.uniform();
    points.push_back(point(error, static_cast<double>(random.below(8)), static_cast<double>(random.below(3))));
  }
  return points;
}

// The rank of every point by the definition: front f is what is non-dominated once fronts < f are removed.
std::vector<std::size_t> brute_force_ranks(const std::vector<Fitness>& points, std::size_t objectives) {
  std::vector<std::size_t> rank(points.size(), std::numeric_limits<std::size_t>::max());
  for (std::size_t f = 0, assigned = 0; assigned < points.size(); ++f) {
    std::vector<std::size_t> front;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (rank[i] < f) continue;
      bool dominated = false;
      for (std::size_t j = 0; j < points.size(); ++j)
        dominated = dominated || (rank[j] >= f && dominates(points[j], points[i], objectives));
      if (!dominated) front.push_back(i);
    }
    for (std::size_t i : front) rank[i] = f;
    assigned += front.size();
  }
  return rank;
}

}  // namespace

TEST_CASE("Non-dominated fronts and crowding distances on a known point set", "[gp]") {
  // error, cost: a front of three, a second front of two, one dominated by everything.
  const std::vector<Fitness> points{point(0.1, 9), point(0.5, 2), point(0.2, 5),
                                    point(0.6, 6), point(0.3, 8), point(0.9, 9)};
  const auto fronts = nondominated_fronts(points, 2);
  REQUIRE(fronts.size() == 3);
  CHECK(fronts[0] == std::vector<std::size_t>{0, 1, 2});
  CHECK(fronts[1] == std::vector<std::size_t>{3, 4});
  CHECK(fronts[2] == std::vector<std::size_t>{5});
  const auto distances = crowding_distances(points, fronts[0], 2);
  CHECK(std::isinf(distances[0]));
  CHECK(std::isinf(distances[1]));
  // The middle point: (0.5 - 0.1) / 0.4 for the error plus (9 - 2) / 7 for the cost.
  CHECK(std::abs(distances[2] - 2.0) < 1e-12);
  const ParetoRanking ranking = rank_by_pareto(points, 2);
  CHECK(ranking.rank == std::vector<std::size_t>{0, 0, 0, 1, 1, 2});
  CHECK(ranking.better(2, 3));
  CHECK(ranking.better(0, 2));  // same front, larger crowding distance
}

TEST_CASE("The fast non-dominated sort agrees with the definition, with ties and three objectives", "[gp]") {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    for (std::size_t objectives : {std::size_t{2}, std::size_t{3}}) {
      const auto points = random_points(120, seed, seed % 2 == 0);
      const ParetoRanking ranking = rank_by_pareto(points, objectives);
      CAPTURE(seed, objectives);
      CHECK(ranking.rank == brute_force_ranks(points, objectives));
    }
  }
}

TEST_CASE("Survivors are whole fronts first, duplicates last", "[gp]") {
  const std::vector<Fitness> points{point(0.1, 9), point(0.1, 9), point(0.1, 9),
                                    point(0.5, 2), point(0.6, 6), point(0.3, 8)};
  const auto survivors = select_survivors(points, 4, 2);
  // Distinct points: front {0, 3, 5} then {4}; the copies of point 0 come after them.
  CHECK(survivors == std::vector<std::size_t>{0, 3, 5, 4});
  CHECK(select_survivors(points, 6, 2).size() == 6);
}

TEST_CASE("Tournament with parsimony: lower error wins, a tie goes to the cheaper", "[gp]") {
  CHECK(parsimony_better(point(0.1, 9), point(0.2, 1), 1e-6));
  CHECK(parsimony_better(point(0.1, 2), point(0.1 + 1e-9, 1), 0.0));
  CHECK(parsimony_better(point(0.1 + 1e-9, 1), point(0.1, 2), 1e-6));
  CHECK(parsimony_better(point(1.0, 9), Fitness{}, 0.0));  // unevaluated is the worst
  const std::vector<Fitness> points{point(3, 1), point(1, 5), point(2, 1), point(1, 2)};
  RandomStream random(1, 0);
  std::vector<int> wins(4, 0);
  for (int round = 0; round < 2000; ++round) ++wins[tournament(points, 4, 1e-9, random)];
  CHECK(wins[3] > wins[1]);
  CHECK(wins[1] > wins[0]);
  CHECK(wins[0] < wins[2]);
  CHECK(tournament(points, 1000, 1e-9, random) == 3);
}

TEST_CASE("The archive keeps exactly the non-dominated points it has seen", "[gp]") {
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    for (std::size_t objectives : {std::size_t{2}, std::size_t{3}}) {
      const auto points = random_points(300, seed + 100, seed % 2 == 1);
      ParetoArchive archive(objectives);
      for (std::size_t i = 0; i < points.size(); ++i) archive.insert({Program{}, points[i], i});
      const auto rank = brute_force_ranks(points, objectives);
      // The expected set: front 0, one entry per distinct objective vector, the first one seen.
      std::vector<std::size_t> expected;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const bool first = std::none_of(expected.begin(), expected.end(), [&](std::size_t j) {
          return same_objectives(points[j], points[i], objectives);
        });
        if (rank[i] == 0 && first) expected.push_back(i);
      }
      std::vector<std::size_t> kept;
      for (const ArchiveEntry& entry : archive.entries()) kept.push_back(entry.generation);
      std::sort(kept.begin(), kept.end());
      CAPTURE(seed, objectives);
      CHECK(kept == expected);
      CHECK(std::is_sorted(archive.entries().begin(), archive.entries().end(),
                           [](const auto& a, const auto& b) { return a.fitness.cost < b.fitness.cost; }));
    }
  }
  ParetoArchive archive;
  CHECK_FALSE(archive.insert({Program{}, point(worst_error, 1), 0}));
  CHECK_FALSE(archive.insert({Program{}, Fitness{}, 0}));
}

TEST_CASE("The knee is where more cost stops buying much accuracy", "[gp]") {
  // log10 errors -1, -4, -4.5, -5 at costs 1, 3, 8, 20: the bend is at cost 3.
  const std::vector<Fitness> front{point(1e-1, 1), point(1e-4, 3), point(10.0 * 1e-5 / std::sqrt(10.0), 8),
                                   point(1e-5, 20)};
  CHECK(knee_index(front) == 1);
  CHECK(knee_index(std::vector<Fitness>{point(0.5, 1), point(0.1, 2)}) == 1);  // two members: the most accurate
  const std::vector<Fitness> straight{point(1e-1, 1), point(1e-2, 2), point(1e-3, 3)};
  CHECK(knee_index(straight) == 2);  // nothing below the line
}
