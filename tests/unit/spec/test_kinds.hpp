#pragma once
// Kinds for the spec tests. No real kind's schema exists at this layer, so "lut" here is a test schema
// with a field of every type (including nested sections), and "sweep" a second kind whose section
// must be refused in a lut job.
#include <cstdint>
#include <string>
#include <vector>

#include "pbrfit/spec/job_spec.hpp"

namespace pbrfit::spec::testing {

inline Schema test_lut_schema() {
  Schema n_dot_v("n_dot_v");  // optional, but not defaultable: it has a required key
  n_dot_v.number("min", "Smallest cos(theta_v).").defaults_to(0.0).range(0, 1);
  n_dot_v.number("max", "Largest cos(theta_v).").defaults_to(1.0).range(0, 1);
  n_dot_v.integer("samples", "Samples along n.v.").require().range(1, 4096);

  Schema roughness("roughness");  // optional and defaultable
  roughness.number("min", "Smallest alpha.").defaults_to(0.01).above(0);
  roughness.number("max", "Largest alpha.").defaults_to(1.0).above(0);

  Schema lut("lut");
  lut.choice("function", {"dfg", "directional_albedo", "specular_occlusion"}, "What to tabulate.").require();
  lut.integer_list("resolution", 2, 2, "Table size.")
      .defaults_to(std::vector<std::int64_t>{32, 32})
      .range(1, 4096);
  lut.integer_list("moments", 1, 3, "Moments to store.").defaults_to(std::vector<std::int64_t>{0}).at_least(0);
  lut.number("tolerance", "Absolute error target.").defaults_to(1e-6).above(0);
  lut.integer("max_evaluations", "Integrand calls per entry.").defaults_to(100000).range(1, 1000000000);
  lut.boolean("importance_sampling", "Sample the GGX lobe.").defaults_to(true);
  lut.choice("visibility", {"height_correlated", "separable", "separable_schlick"}, "Smith G form.")
      .defaults_to("height_correlated");
  lut.string("label", "Free text; no default.");
  lut.section("n_dot_v", n_dot_v, "Viewing angles.");
  lut.section("roughness", roughness, "Roughness range.");
  return lut;
}

// A sweep section with lists of every kind: axes (mappings), weights (numbers), operators (names).
inline Schema test_sweep_schema() {
  Schema axis("axis");
  axis.string("name", "Axis name.").require();
  axis.integer("count", "Samples.").defaults_to(8).range(1, 1024);
  Schema sweep("sweep");
  sweep.integer("steps", "Sweep steps.").defaults_to(10).at_least(1);
  sweep.section_list("axes", axis, 0, 4, "Grid axes.");
  sweep.section_list("levels", axis, 1, unbounded, "At least one level.");
  sweep.number_list("weights", 1, 3, "Weights.").defaults_to(std::vector<double>{1.0}).range(0, 10);
  sweep.string_list("operators", 1, unbounded, "Operators.", {"add", "mul", "sin"})
      .defaults_to(std::vector<std::string>{"add"});
  sweep.string_list("tags", 0, 2, "Free names.").defaults_to(std::vector<std::string>{});
  return sweep;
}

inline const KindCatalogue& test_kinds() {
  static const Schema lut = test_lut_schema();
  static const Schema sweep = test_sweep_schema();
  static const KindCatalogue kinds{
      {"lut", "sweep"},
      [](const std::string& kind) -> const Schema& { return kind == "lut" ? lut : sweep; }};
  return kinds;
}

}  // namespace pbrfit::spec::testing
