#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include "pbrfit/brdf/split_sum_dfg.hpp"
#include "pbrfit/jobs/lut/dfg_table.hpp"

using namespace pbrfit;
using jobs::lut::DfgSettings;
using jobs::lut::DfgTable;

namespace {

DfgSettings small(bool multiple_scattering) {
  DfgSettings s;
  s.n_dot_v_count = 5;
  s.roughness_count = 4;
  s.multiple_scattering = multiple_scattering;
  return s;
}

const store::Block& find(const std::vector<store::Block>& blocks, const std::string& table) {
  for (const auto& b : blocks)
    if (b.table == table) return b;
  FAIL("no block for " << table);
  throw;
}

// Item `item` of stage 0, as the runtime would hand it to a compute thread.
Bytes compute(const DfgTable& table, std::uint64_t item) {
  const Bytes nothing;
  return table.compute(runtime::ItemTask{{0, item}, nothing, nothing, 0});
}

}  // namespace

TEST_CASE("the DFG layout names its axes and parametrization") {
  const auto layout = DfgTable(small(true)).layout();
  REQUIRE(layout.groups.size() == 1);
  const auto& g = layout.groups[0];
  CHECK(g.name == "dfg");
  CHECK(g.attributes.at("roughness_parametrization") == "alpha = r^2");
  CHECK(g.axis("n_dot_v").values == std::vector<double>{0.1, 0.3, 0.5, 0.7, 0.9});
  CHECK(g.axis("roughness").values == std::vector<double>{0.125, 0.375, 0.625, 0.875});
  std::vector<std::string> tables;
  for (const auto& t : g.tables) tables.push_back(t.name);
  CHECK(tables == std::vector<std::string>{"scale", "bias", "error_estimate", "evaluations", "alpha", "energy",
                                           "average_energy"});
}

TEST_CASE("a DFG row is the engine's entries, placed at its row") {
  const DfgTable table(small(true));
  const auto blocks = table.blocks({0, 2}, compute(table, 2));
  const auto& scale = find(blocks, "scale");
  const auto& bias = find(blocks, "bias");
  CHECK(scale.offset == std::vector<std::uint64_t>{2, 0});
  CHECK(scale.count == std::vector<std::uint64_t>{1, 5});
  const double alpha = 0.625 * 0.625;
  CHECK(find(blocks, "alpha").values == store::reals(std::vector<double>{alpha}));
  const auto entry = brdf::integrate_dfg(0.5, alpha, brdf::SmithVisibility::height_correlated, {});
  CHECK(scale.values[2] == entry.scale);
  CHECK(bias.values[2] == entry.bias);
  CHECK(find(blocks, "energy").values[2] == entry.scale + entry.bias);
  const auto average = brdf::integrate_average_albedo(alpha, brdf::SmithVisibility::height_correlated, {});
  CHECK(find(blocks, "average_energy").values == store::reals(std::vector<double>{average.value}));
}

TEST_CASE("the gloss parametrization names its axis gloss and maps alpha = (1 - g)^4") {
  auto s = small(false);
  s.roughness = brdf::RoughnessParametrization::gloss;
  s.placement = jobs::lut::Placement::edges;
  const DfgTable table(s);
  CHECK(table.layout().groups[0].axis("gloss").values == std::vector<double>{0.0, 1.0 / 3, 2.0 / 3, 1.0});
  const auto blocks = table.blocks({0, 3}, compute(table, 3));
  CHECK(find(blocks, "alpha").values == store::reals(std::vector<double>{0.0}));
  // gloss 1 is the mirror: scale + bias = 1 exactly at every n.v
  for (std::size_t i = 0; i < 5; ++i)
    CHECK_THAT(find(blocks, "scale").values[i].real() + find(blocks, "bias").values[i].real(), Catch::Matchers::WithinAbs(1.0, 1e-15));
}

TEST_CASE("an entry that misses the tolerance fails the item with what to change") {
  auto s = small(false);
  s.integration.abs_tolerance = 1e-12;
  s.integration.max_evaluations = 1000;
  REQUIRE_THROWS_WITH(compute(DfgTable(s), 1),
                      Catch::Matchers::ContainsSubstring("did not reach the tolerance") &&
                          Catch::Matchers::ContainsSubstring("raise max_evaluations"));
}

TEST_CASE("the headline summarizes accuracy and cost of the rows so far") {
  const DfgTable table(small(false));
  Bytes summary;
  CHECK(table.headline(summary) == "no entries yet");
  table.fold_summary(summary, {0, 0}, compute(table, 0));
  CHECK_THAT(table.headline(summary), Catch::Matchers::StartsWith("5 entries, max error estimate"));
  table.fold_summary(summary, {0, 1}, compute(table, 1));
  CHECK_THAT(table.headline(summary), Catch::Matchers::StartsWith("10 entries, max error estimate"));
}
